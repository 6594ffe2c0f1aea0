// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "CellQualityScan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace dcprbf
{

namespace
{

inline void cross(const double* a, const double* b, double* c)
{
    c[0] = a[1]*b[2] - a[2]*b[1];
    c[1] = a[2]*b[0] - a[0]*b[2];
    c[2] = a[0]*b[1] - a[1]*b[0];
}

inline double dot(const double* a, const double* b)
{
    return a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
}

inline void measures
(
    const double* r0, const double* r1, const double* r2, const double* r3,
    const double* c0, const double* c1, const double* c2, const double* c3,
    double& J,
    double& a2
)
{
    // Edge matrices (columns e_k, f_k: edges from vertex 0)
    double e[3][3], f[3][3];
    for (int d = 0; d < 3; ++d)
    {
        e[0][d] = r1[d] - r0[d]; e[1][d] = r2[d] - r0[d]; e[2][d] = r3[d] - r0[d];
        f[0][d] = c1[d] - c0[d]; f[1][d] = c2[d] - c0[d]; f[2][d] = c3[d] - c0[d];
    }
    // E0^-1 = (rows e1 x e2, e2 x e0, e0 x e1)/det0
    double adj[3][3];
    cross(e[1], e[2], adj[0]);
    cross(e[2], e[0], adj[1]);
    cross(e[0], e[1], adj[2]);
    const double det0 = dot(e[0], adj[0]);
    const double scale2 = std::max({dot(e[0], e[0]), dot(e[1], e[1]), dot(e[2], e[2])});
    if (!(det0*det0 > 1e-28*scale2*scale2*scale2))
    {
        J = a2 = -1;   // degenerate reference (TetQuality::compute: q = 1)
        return;
    }
    double f12[3];
    cross(f[1], f[2], f12);
    J = dot(f[0], f12)/det0;
    // |A|_F^2, A det0 = E adj: (E adj)_ij = sum_k f_k[i] adj_k[j]
    a2 = 0;
    for (int i = 0; i < 3; ++i)
    {
        for (int j = 0; j < 3; ++j)
        {
            const double v = f[0][i]*adj[0][j] + f[1][i]*adj[1][j] + f[2][i]*adj[2][j];
            a2 += v*v;
        }
    }
    a2 /= det0*det0;
}


//- Keys ranked in place of the quality: where q^6 neither underflows nor
//  overflows (outside, the quality itself is compared)
constexpr double keyFloor = 1e-250;
constexpr double keyCeiling = 1e250;

} // namespace


CellQualityScan::CellQualityScan
(
    std::vector<std::size_t> cellStart,
    std::vector<int> cellFaces,
    std::vector<std::size_t> faceStart,
    std::vector<int> facePoints,
    const double* points0,
    TetQuality::Metric metric
)
:
    cellStart_(std::move(cellStart)),
    cellFaces_(std::move(cellFaces)),
    faceStart_(std::move(faceStart)),
    facePoints_(std::move(facePoints)),
    metric_(metric),
    faceCentres0_(3*cellFaces_.size()),
    cellCentres0_(3*(cellStart_.empty() ? 0 : cellStart_.size() - 1))
{
    if (cellStart_.empty() || cellStart_.back() != cellFaces_.size()
     || faceStart_.empty() || faceStart_.back() != facePoints_.size())
    {
        throw std::invalid_argument("CellQualityScan: inconsistent compressed rows");
    }
    const std::size_t nFaces = faceStart_.size() - 1;
    for (const int f : cellFaces_)
    {
        if (f < 0 || std::size_t(f) >= nFaces || faceStart_[f + 1] - faceStart_[f] < 3)
        {
            throw std::invalid_argument("CellQualityScan: face index or face size");
        }
    }

    // The points renumbered in the order in which the cells use them (a
    // measurement reads them from a compact copy, mostly in order)
    int maxIndex = -1;
    for (const int pi : facePoints_)
    {
        if (pi < 0) throw std::invalid_argument("CellQualityScan: point index");
        maxIndex = std::max(maxIndex, pi);
    }
    std::vector<int> local(std::size_t(maxIndex + 1), -1);
    for (const int f : cellFaces_)
    {
        for (std::size_t j = faceStart_[f]; j < faceStart_[f + 1]; ++j)
        {
            if (local[facePoints_[j]] < 0)
            {
                local[facePoints_[j]] = int(pointIds_.size());
                pointIds_.push_back(facePoints_[j]);
            }
        }
    }
    for (int& pi : facePoints_) pi = local[pi];
    points0_.resize(3*pointIds_.size());
    for (std::size_t i = 0; i < pointIds_.size(); ++i)
    {
        for (int d = 0; d < 3; ++d) points0_[3*i + d] = points0[3*std::size_t(pointIds_[i]) + d];
    }
    for (std::size_t i = 0; i + 1 < cellStart_.size(); ++i)
    {
        double* cc = &cellCentres0_[3*i];
        cc[0] = cc[1] = cc[2] = 0;
        for (std::size_t k = cellStart_[i]; k < cellStart_[i + 1]; ++k)
        {
            const int f = cellFaces_[k];
            double* fc = &faceCentres0_[3*k];
            fc[0] = fc[1] = fc[2] = 0;
            for (std::size_t j = faceStart_[f]; j < faceStart_[f + 1]; ++j)
            {
                for (int d = 0; d < 3; ++d) fc[d] += points0_[3*std::size_t(facePoints_[j]) + d];
            }
            const double n = double(faceStart_[f + 1] - faceStart_[f]);
            for (int d = 0; d < 3; ++d)
            {
                fc[d] /= n;
                cc[d] += fc[d];
            }
        }
        const double n = double(cellStart_[i + 1] - cellStart_[i]);
        for (int d = 0; d < 3; ++d) cc[d] /= n;
    }
}


void CellQualityScan::tetMeasures
(
    const double* r0, const double* r1, const double* r2, const double* r3,
    const double* c0, const double* c1, const double* c2, const double* c3,
    double& J,
    double& a2
)
{
    measures(r0, r1, r2, r3, c0, c1, c2, c3, J, a2);
}


double CellQualityScan::quality(const double J, const double a2, const TetQuality::Metric metric)
{
    if (a2 < 0)
    {
        return 1.0;
    }
    if (!(J > 0))
    {
        return J;
    }
    const double fSize = std::min(J, 1.0/J);
    const double fShape = 3.0*std::cbrt(J*J)/a2;
    switch (metric)
    {
        case TetQuality::Metric::size: return fSize;
        case TetQuality::Metric::shape: return fShape;
        default: return std::sqrt(fSize)*fShape;
    }
}


double CellQualityScan::rankKey(const double J, const double a2, const TetQuality::Metric metric)
{
    // q^6 (sizeShape: min(J, 1/J)^3 729 J^4/a2^6), q^3 (shape), q (size)
    switch (metric)
    {
        case TetQuality::Metric::size: return std::min(J, 1.0/J);
        case TetQuality::Metric::shape: return 27.0*J*J/(a2*a2*a2);
        default:
        {
            const double a6 = a2*a2*a2;
            const double J4 = (J*J)*(J*J);
            return 729.0*(J < 1 ? J4*(J*J*J) : J)/(a6*a6);
        }
    }
}


double CellQualityScan::tetQuality
(
    const double* r0, const double* r1, const double* r2, const double* r3,
    const double* c0, const double* c1, const double* c2, const double* c3,
    TetQuality::Metric metric
)
{
    double J, a2;
    tetMeasures(r0, r1, r2, r3, c0, c1, c2, c3, J, a2);
    return quality(J, a2, metric);
}


double CellQualityScan::cellQuality
(
    const std::size_t i,
    const double* p,
    std::vector<double>& buf
) const
{
    const std::size_t k0 = cellStart_[i], k1 = cellStart_[i + 1];
    buf.resize(3*(k1 - k0));
    double cc[3] = {0, 0, 0};
    for (std::size_t k = k0; k < k1; ++k)
    {
        const int fi = cellFaces_[k];
        double* fc = &buf[3*(k - k0)];
        fc[0] = fc[1] = fc[2] = 0;
        for (std::size_t j = faceStart_[fi]; j < faceStart_[fi + 1]; ++j)
        {
            const double* x = p + 3*std::size_t(facePoints_[j]);
            fc[0] += x[0]; fc[1] += x[1]; fc[2] += x[2];
        }
        const double n = double(faceStart_[fi + 1] - faceStart_[fi]);
        for (int d = 0; d < 3; ++d)
        {
            fc[d] /= n;
            cc[d] += fc[d];
        }
    }
    for (int d = 0; d < 3; ++d) cc[d] /= double(k1 - k0);

    // The worst tetrahedron by a monotone function of its quality without
    // cbrt and sqrt (rankKey); its quality computed once. Inverted and
    // degenerate ones and keys out of the key's range (underflow) compare
    // by their quality.
    const double* cc0 = &cellCentres0_[3*i];
    double qOther = std::numeric_limits<double>::max();
    double bestKey = std::numeric_limits<double>::max(), bestJ = 1, bestA2 = 3;
    for (std::size_t k = k0; k < k1; ++k)
    {
        const int fi = cellFaces_[k];
        const double* fc0 = &faceCentres0_[3*k];
        const double* fc = &buf[3*(k - k0)];
        const std::size_t j0 = faceStart_[fi], j1 = faceStart_[fi + 1];
        for (std::size_t j = j0; j < j1; ++j)
        {
            const std::size_t a = std::size_t(facePoints_[j]);
            const std::size_t b = std::size_t(facePoints_[j + 1 < j1 ? j + 1 : j0]);
            double J, a2;
            const double* p0 = points0_.data();
            measures(cc0, fc0, p0 + 3*a, p0 + 3*b, cc, fc, p + 3*a, p + 3*b, J, a2);
            const double key = (J > 0 && a2 > 0) ? rankKey(J, a2, metric_) : 0;
            if (key > keyFloor && key < keyCeiling)
            {
                if (key < bestKey)
                {
                    bestKey = key;
                    bestJ = J;
                    bestA2 = a2;
                }
            }
            else
            {
                qOther = std::min(qOther, quality(J, a2, metric_));
            }
        }
    }
    return std::min(qOther, bestKey < std::numeric_limits<double>::max()
        ? quality(bestJ, bestA2, metric_) : qOther);
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
        std::vector<double> buf;
        #pragma omp for schedule(static, 256)
        for (long i = 0; i < n; ++i)
        {
            q[i] = cellQuality(std::size_t(i), x.data(), buf);
        }
    }
}

} // namespace dcprbf
