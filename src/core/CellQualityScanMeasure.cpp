// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// CellQualityScan: the measurement (the construction is in CellQualityScan.cpp).
#include "CellQualityScan.hpp"
#include "TetMeasures.hpp"

#include <algorithm>

namespace dcprbf
{

bool CellQualityScan::tetVertices(const std::size_t k0, int v[4]) const
{
    // four triangles: the first face's points and the one point of the
    // second face that is not among them
    for (std::size_t k = k0; k < k0 + 4; ++k)
    {
        const int f = cellFaces_[k];
        if (faceStart_[f + 1] - faceStart_[f] != 3) return false;
    }
    const int* a = &facePoints_[faceStart_[cellFaces_[k0]]];
    const int* b = &facePoints_[faceStart_[cellFaces_[k0 + 1]]];
    v[0] = a[0]; v[1] = a[1]; v[2] = a[2];
    for (int j = 0; j < 3; ++j)
    {
        if (b[j] != a[0] && b[j] != a[1] && b[j] != a[2])
        {
            v[3] = b[j];
            return true;
        }
    }
    return false;
}


double CellQualityScan::cellQuality
(
    const std::size_t i,
    const double* x,
    std::vector<double>& buf,
    std::vector<double>& pointBuf
) const
{
    const std::size_t k0 = cellStart_[i], k1 = cellStart_[i + 1];
    if (k1 - k0 == 4)
    {
        int v[4];
        if (tetVertices(k0, v))
        {
            // Every tetrahedron of the decomposition is an affine image of
            // the cell's (its centres are fixed combinations of the cell's
            // vertices): each has the cell's own A. One measure.
            const double* x0 = points0_.data();
            double J, a2;
            TetMeasures::measures
            (
                x0 + 3*v[0], x0 + 3*v[1], x0 + 3*v[2], x0 + 3*v[3],
                x + 3*v[0], x + 3*v[1], x + 3*v[2], x + 3*v[3], J, a2
            );
            return TetMeasures::quality(J, a2, metric_);
        }
    }
    buf.resize(3*(k1 - k0));
    double cc[3] = {0, 0, 0};
    for (std::size_t k = k0; k < k1; ++k)
    {
        const int fi = cellFaces_[k];
        double* fc = &buf[3*(k - k0)];
        fc[0] = fc[1] = fc[2] = 0;
        for (std::size_t j = faceStart_[fi]; j < faceStart_[fi + 1]; ++j)
        {
            const double* y = x + 3*std::size_t(facePoints_[j]);
            fc[0] += y[0]; fc[1] += y[1]; fc[2] += y[2];
        }
        const double n = double(faceStart_[fi + 1] - faceStart_[fi]);
        for (int d = 0; d < 3; ++d)
        {
            fc[d] /= n;
            cc[d] += fc[d];
        }
    }
    for (int d = 0; d < 3; ++d) cc[d] /= double(k1 - k0);

    // The tetrahedra of face k: (cc, fc, a_j, a_j+1). Per face point (its
    // vertices' edges from the cell centre, the cross products with the
    // face centre's edge) once, shared by the face's two tetrahedra at it.
    // The worst tetrahedron by a monotone function of its quality without
    // cbrt and sqrt (rankKey); its quality computed once. Inverted and
    // degenerate ones and keys out of the key's range compare by their
    // quality.
    const double* cc0 = &cellCentres0_[3*i];
    const double* x0 = points0_.data();
    TetMeasures::Worst worst(metric_);
    for (std::size_t k = k0; k < k1; ++k)
    {
        const int fi = cellFaces_[k];
        const double* fc0 = &faceCentres0_[3*k];
        const double* fc = &buf[3*(k - k0)];
        const std::size_t j0 = faceStart_[fi], n = faceStart_[fi + 1] - j0;
        double e0[3], f0[3];
        for (int d = 0; d < 3; ++d)
        {
            e0[d] = fc0[d] - cc0[d];
            f0[d] = fc[d] - cc[d];
        }
        const double s0 = TetMeasures::dot(e0, e0);

        // per point: e (3), f (3), w = e0 x e (3), g = f0 x f (3), |e|^2
        pointBuf.resize(13*n);
        for (std::size_t j = 0; j < n; ++j)
        {
            double* r = &pointBuf[13*j];
            const std::size_t pi = 3*std::size_t(facePoints_[j0 + j]);
            for (int d = 0; d < 3; ++d)
            {
                r[d] = x0[pi + d] - cc0[d];
                r[3 + d] = x[pi + d] - cc[d];
            }
            TetMeasures::cross(e0, r, r + 6);
            TetMeasures::cross(f0, r + 3, r + 9);
            r[12] = TetMeasures::dot(r, r);
        }
        for (std::size_t j = 0; j < n; ++j)
        {
            const double* ra = &pointBuf[13*j];
            const double* rb = &pointBuf[13*(j + 1 < n ? j + 1 : 0)];
            // E0 = (e0, ea, eb), E0^-1 det0 = rows (ea x eb, eb x e0, e0 x ea)
            double adj0[3];
            TetMeasures::cross(ra, rb, adj0);
            const double adj1[3] = {-rb[6], -rb[7], -rb[8]};
            const double* adj2 = ra + 6;
            const double det0 = TetMeasures::dot(e0, adj0);
            const double scale2 = std::max({s0, ra[12], rb[12]});
            double J = -1, a2 = -1;
            if (det0*det0 > 1e-28*scale2*scale2*scale2)
            {
                // E = (f0, fa, fb): det E = fb . (f0 x fa)
                J = TetMeasures::dot(rb + 3, ra + 9)/det0;
                a2 = 0;
                for (int r = 0; r < 3; ++r)
                {
                    for (int c = 0; c < 3; ++c)
                    {
                        const double v = f0[r]*adj0[c] + ra[3 + r]*adj1[c] + rb[3 + r]*adj2[c];
                        a2 += v*v;
                    }
                }
                a2 /= det0*det0;
            }
            worst.add(J, a2);
        }
    }
    return worst.quality();
}


void CellQualityScan::measure(const double* p, double* q) const
{
    const long nPoints = long(pointIds_.size());
    std::vector<double> x(3*pointIds_.size());
    const long n = long(size());
    #pragma omp parallel
    {
        #pragma omp for schedule(static)
        for (long i = 0; i < nPoints; ++i)
        {
            const double* y = p + 3*std::size_t(pointIds_[i]);
            x[3*i] = y[0];
            x[3*i + 1] = y[1];
            x[3*i + 2] = y[2];
        }
        std::vector<double> buf, pointBuf;
        #pragma omp for schedule(static, 256)
        for (long i = 0; i < n; ++i)
        {
            q[order_[i]] = cellQuality(std::size_t(i), x.data(), buf, pointBuf);
        }
    }
}

} // namespace dcprbf
