// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "PlanarCellQualityScan.hpp"
#include "TetMeasures.hpp"

#include <algorithm>
#include <stdexcept>

namespace dcprbf
{

PlanarCellQualityScan::PlanarCellQualityScan
(
    std::vector<std::size_t> polygonStart,
    std::vector<int> polygonPoints,
    const double* points0,
    const int axis0,
    const int axis1,
    TetQuality::Metric metric
)
:
    polygonStart_(std::move(polygonStart)),
    polygonPoints_(std::move(polygonPoints)),
    axis0_(axis0),
    axis1_(axis1),
    metric_(metric)
{
    if (polygonStart_.empty() || polygonStart_.back() != polygonPoints_.size())
    {
        throw std::invalid_argument("PlanarCellQualityScan: inconsistent compressed rows");
    }
    if (axis0_ < 0 || axis0_ > 2 || axis1_ < 0 || axis1_ > 2 || axis0_ == axis1_)
    {
        throw std::invalid_argument("PlanarCellQualityScan: axes");
    }
    int maxIndex = -1;
    for (std::size_t i = 0; i + 1 < polygonStart_.size(); ++i)
    {
        if (polygonStart_[i + 1] < polygonStart_[i] + 3)
        {
            throw std::invalid_argument("PlanarCellQualityScan: polygon size");
        }
    }
    for (const int pi : polygonPoints_)
    {
        if (pi < 0) throw std::invalid_argument("PlanarCellQualityScan: point index");
        maxIndex = std::max(maxIndex, pi);
    }

    // The points renumbered in order of use (read from a compact copy)
    std::vector<int> local(std::size_t(maxIndex + 1), -1);
    for (int& pi : polygonPoints_)
    {
        if (local[pi] < 0)
        {
            local[pi] = int(pointIds_.size());
            pointIds_.push_back(pi);
        }
        pi = local[pi];
    }
    points0_.resize(2*pointIds_.size());
    for (std::size_t i = 0; i < pointIds_.size(); ++i)
    {
        points0_[2*i] = points0[3*std::size_t(pointIds_[i]) + axis0_];
        points0_[2*i + 1] = points0[3*std::size_t(pointIds_[i]) + axis1_];
    }
    centres0_.assign(2*size(), 0.0);
    for (std::size_t i = 0; i < size(); ++i)
    {
        const std::size_t j0 = polygonStart_[i], j1 = polygonStart_[i + 1];
        for (std::size_t j = j0; j < j1; ++j)
        {
            centres0_[2*i] += points0_[2*polygonPoints_[j]];
            centres0_[2*i + 1] += points0_[2*polygonPoints_[j] + 1];
        }
        centres0_[2*i] /= double(j1 - j0);
        centres0_[2*i + 1] /= double(j1 - j0);
    }
}


double PlanarCellQualityScan::cellQuality(const std::size_t i, const double* x) const
{
    const std::size_t j0 = polygonStart_[i], j1 = polygonStart_[i + 1];
    const double n = double(j1 - j0);
    double c[2] = {0, 0};
    for (std::size_t j = j0; j < j1; ++j)
    {
        c[0] += x[2*polygonPoints_[j]];
        c[1] += x[2*polygonPoints_[j] + 1];
    }
    c[0] /= n;
    c[1] /= n;
    const double* c0 = &centres0_[2*i];

    // Triangle (centre, a, b): reference edges ea, eb, current fa, fb;
    // F det0 = (fa fb) adj(ea eb)
    TetMeasures::Worst worst(metric_);
    for (std::size_t j = j0; j < j1; ++j)
    {
        const int a = polygonPoints_[j], b = polygonPoints_[j + 1 < j1 ? j + 1 : j0];
        const double ea[2] = {points0_[2*a] - c0[0], points0_[2*a + 1] - c0[1]};
        const double eb[2] = {points0_[2*b] - c0[0], points0_[2*b + 1] - c0[1]};
        const double fa[2] = {x[2*a] - c[0], x[2*a + 1] - c[1]};
        const double fb[2] = {x[2*b] - c[0], x[2*b + 1] - c[1]};
        const double det0 = ea[0]*eb[1] - ea[1]*eb[0];
        const double scale2 = std::max(ea[0]*ea[0] + ea[1]*ea[1], eb[0]*eb[0] + eb[1]*eb[1]);
        double J = -1, a2 = -1;   // degenerate reference: quality 1
        if (det0*det0 > 1e-28*scale2*scale2)
        {
            J = (fa[0]*fb[1] - fa[1]*fb[0])/det0;
            const double m00 = fa[0]*eb[1] - fb[0]*ea[1];
            const double m01 = fb[0]*ea[0] - fa[0]*eb[0];
            const double m10 = fa[1]*eb[1] - fb[1]*ea[1];
            const double m11 = fb[1]*ea[0] - fa[1]*eb[0];
            a2 = (m00*m00 + m01*m01 + m10*m10 + m11*m11)/(det0*det0) + 1;
        }
        worst.add(J, a2);
    }
    return worst.quality();
}


void PlanarCellQualityScan::measure(const double* p, double* q) const
{
    const long nPoints = long(pointIds_.size());
    std::vector<double> x(2*pointIds_.size());
    const long n = long(size());
    #pragma omp parallel
    {
        #pragma omp for schedule(static)
        for (long i = 0; i < nPoints; ++i)
        {
            x[2*i] = p[3*std::size_t(pointIds_[i]) + axis0_];
            x[2*i + 1] = p[3*std::size_t(pointIds_[i]) + axis1_];
        }
        #pragma omp for schedule(static, 256)
        for (long i = 0; i < n; ++i)
        {
            q[i] = cellQuality(std::size_t(i), x.data());
        }
    }
}

} // namespace dcprbf
