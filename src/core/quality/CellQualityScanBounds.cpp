// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// CellQualityScan: the measurement of the cells that rank the k lowest
// (measureLowest), the others bounded (CellQualityBound).
#include "CellQualityScan.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dcprbf
{

namespace
{

//- The prism's faces (CellShapes' vertex order): two triangles, three
//  quadrilaterals
const int prismFaces[5][4] =
{
    {0, 1, 2, -1}, {3, 4, 5, -1}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}
};

//- The hexahedron's faces (CellShapes' vertex order)
const int hexFaces[6][4] =
{
    {0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}
};

//- Largest |E^-1|_F of the tetrahedra (c, face centre, a, b) of a cell:
//  faces given by their points' reference coordinates (face f: the points
//  at x0 + 3 pts[start[f] .. start[f+1]))
template<class Face>
double largestInverseNorm(const double* x0, const std::size_t nFaces, const Face& face)
{
    // face centres, the cell centre: averages, as CellQualityScan's
    std::vector<double> fc(3*nFaces);
    double cc[3] = {0, 0, 0};
    for (std::size_t f = 0; f < nFaces; ++f)
    {
        int n = 0;
        const int* pts = face(f, n);
        double* c = &fc[3*f];
        c[0] = c[1] = c[2] = 0;
        for (int j = 0; j < n; ++j)
        {
            for (int d = 0; d < 3; ++d) c[d] += x0[3*std::size_t(pts[j]) + d];
        }
        for (int d = 0; d < 3; ++d)
        {
            c[d] /= n;
            cc[d] += c[d];
        }
    }
    for (int d = 0; d < 3; ++d) cc[d] /= double(nFaces);
    double kappa = 0;
    for (std::size_t f = 0; f < nFaces; ++f)
    {
        int n = 0;
        const int* pts = face(f, n);
        for (int j = 0; j < n; ++j)
        {
            const double* a = x0 + 3*std::size_t(pts[j]);
            const double* b = x0 + 3*std::size_t(pts[j + 1 < n ? j + 1 : 0]);
            double e0[3], ea[3], eb[3];
            for (int d = 0; d < 3; ++d)
            {
                e0[d] = fc[3*f + d] - cc[d];
                ea[d] = a[d] - cc[d];
                eb[d] = b[d] - cc[d];
            }
            kappa = std::max(kappa, CellQualityBound::inverseNorm(e0, ea, eb));
        }
    }
    return kappa;
}

//- The j-th lowest of values (reordered for it)
inline double nthLowest(std::vector<double>& values, const std::size_t j)
{
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(j), values.end());
    return values[j];
}

} // namespace


double CellQualityScan::kappa(const std::size_t i) const
{
    const double* x0 = points0_.data();
    if (kind_[i] == prism || kind_[i] == hexahedron)
    {
        const int* v = &vertices_[std::size_t(slot_[i])];
        const bool hex = kind_[i] == hexahedron;
        int pts[4];
        return largestInverseNorm
        (
            x0, hex ? 6 : 5,
            [&](const std::size_t f, int& n) -> const int*
            {
                const int* face = hex ? hexFaces[f] : prismFaces[f];
                n = face[3] < 0 ? 3 : 4;
                for (int j = 0; j < n; ++j) pts[j] = v[face[j]];
                return pts;
            }
        );
    }
    const std::size_t g = std::size_t(slot_[i]), k0 = cellStart_[g];
    return largestInverseNorm
    (
        x0, cellStart_[g + 1] - k0,
        [&](const std::size_t f, int& n) -> const int*
        {
            const std::size_t k = k0 + f;
            n = int(faceStart_[k + 1] - faceStart_[k]);
            return &facePoints_[faceStart_[k]];
        }
    );
}


void CellQualityScan::setUpBounds() const
{
    const std::size_t n = size();
    bounds_.assign(n, CellQualityBound());
    boundStart_.assign(n + 1, 0);
    boundVertices_.clear();
    std::vector<int> v;
    for (std::size_t i = 0; i < n; ++i)
    {
        // a tetrahedron is measured as cheaply as bounded: never bounded
        v.clear();
        if (kind_[i] == prism || kind_[i] == hexahedron)
        {
            const int* pv = &vertices_[std::size_t(slot_[i])];
            v.assign(pv, pv + nVertices(kind_[i]));
        }
        else if (kind_[i] == general)
        {
            const std::size_t g = std::size_t(slot_[i]);
            v.assign
            (
                facePoints_.begin() + std::ptrdiff_t(faceStart_[cellStart_[g]]),
                facePoints_.begin() + std::ptrdiff_t(faceStart_[cellStart_[g + 1]])
            );
            std::sort(v.begin(), v.end());
            v.erase(std::unique(v.begin(), v.end()), v.end());
        }
        if (!v.empty())
        {
            bounds_[i] = CellQualityBound(points0_.data(), v.data(), int(v.size()), kappa(i));
        }
        if (!bounds_[i].bounded())
        {
            v.clear();
        }
        boundVertices_.insert(boundVertices_.end(), v.begin(), v.end());
        boundStart_[i + 1] = boundVertices_.size();
    }
}


void CellQualityScan::lowerBounds(const double* p, double* lb) const
{
    if (bounds_.size() != size())
    {
        setUpBounds();
    }
    const std::size_t n = size();
    const bool parallel = n >= minParallelCells;
    const double* x = gather(p, parallel);
    const double* x0 = points0_.data();
    #pragma omp parallel for schedule(static, 256) if(parallel)
    for (long li = 0; li < long(n); ++li)
    {
        const std::size_t i = std::size_t(li);
        const int* v = boundVertices_.data() + boundStart_[i];
        const double b = bounds_[i].lower
        (
            x0, x, v, int(boundStart_[i + 1] - boundStart_[i]), metric_
        );
        // (not-a-number, from points that are: no bound)
        lb[order_[i]] = b == b ? b : -std::numeric_limits<double>::infinity();
    }
}


std::size_t CellQualityScan::measureLowest
(
    const double* p,
    double* q,
    const std::size_t k,
    const bool wide
) const
{
    const std::size_t n = size();
    if (k >= n)
    {
        measure(p, q, wide);
        return n;
    }
    if (bounds_.size() != n)
    {
        setUpBounds();
    }

    // the bounds (in the caller's order, as q)
    lower_.resize(n);
    lowerBounds(p, lower_.data());
    const double* x = compact_.get();

    // the cells whose bound is below the k-th lowest bound (at least k)
    std::vector<double> sorted = lower_;
    const double t0 = nthLowest(sorted, std::max<std::size_t>(k, 1) - 1);
    std::vector<char> measured(n, 0);
    const auto measureWhere = [&](const auto& select)
    {
        pick_.clear();
        for (std::size_t i = 0; i < n; ++i)
        {
            const double b = lower_[std::size_t(order_[i])];
            if (!measured[i] && select(b))
            {
                measured[i] = 1;
                pick_.push_back(int(i));
            }
        }
        measureCells(pick_, x, q, wide);
    };
    measureWhere([&](const double b) { return b <= t0; });

    // the k-th lowest quality measured; then every cell whose bound is not
    // above it (or above 0)
    sorted.clear();
    for (std::size_t i = 0; i < n; ++i)
    {
        if (measured[i]) sorted.push_back(q[order_[i]]);
    }
    if (sorted.empty())
    {
        // (not reached: at least k bounds are at most the k-th lowest)
        measure(p, q, wide);
        return n;
    }
    const std::size_t j = std::min(std::max<std::size_t>(k, 1), sorted.size()) - 1;
    const double theta = std::max(nthLowest(sorted, j), 0.0) + 1e-9;
    measureWhere([&](const double b) { return b <= theta; });
    return boundTheRest(measured, q);
}


std::size_t CellQualityScan::boundTheRest
(
    const std::vector<char>& measured,
    double* q
) const
{
    std::size_t nMeasured = 0;
    for (std::size_t i = 0; i < size(); ++i)
    {
        if (measured[i])
        {
            ++nMeasured;
        }
        else
        {
            q[order_[i]] = lower_[std::size_t(order_[i])];
        }
    }
    return nMeasured;
}

} // namespace dcprbf
