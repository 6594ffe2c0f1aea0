// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "PlanarCellQualityScan.hpp"
#include "TetBatch.hpp"
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
    // Per triangle (centre, a, b) the inverse of its reference edges
    // E0 = (a0 - c0, b0 - c0), once: a measurement needs F = E E0^-1 only
    const auto at = [&](const int k, const int d)
    {
        return points0[3*std::size_t(pointIds_[std::size_t(k)]) + (d ? axis1_ : axis0_)];
    };
    inverse0_.resize(4*polygonPoints_.size());
    degenerate_.assign(polygonPoints_.size(), 0);
    for (std::size_t i = 0; i < size(); ++i)
    {
        const std::size_t j0 = polygonStart_[i], j1 = polygonStart_[i + 1];
        double c0[2] = {0, 0};
        for (std::size_t j = j0; j < j1; ++j)
        {
            for (int d = 0; d < 2; ++d) c0[d] += at(polygonPoints_[j], d);
        }
        for (int d = 0; d < 2; ++d) c0[d] /= double(j1 - j0);
        for (std::size_t j = j0; j < j1; ++j)
        {
            const int a = polygonPoints_[j], b = polygonPoints_[j + 1 < j1 ? j + 1 : j0];
            const double ea[2] = {at(a, 0) - c0[0], at(a, 1) - c0[1]};
            const double eb[2] = {at(b, 0) - c0[0], at(b, 1) - c0[1]};
            const double det0 = ea[0]*eb[1] - ea[1]*eb[0];
            const double scale2 = std::max(ea[0]*ea[0] + ea[1]*ea[1], eb[0]*eb[0] + eb[1]*eb[1]);
            double* inv = &inverse0_[4*j];
            if (det0*det0 > 1e-28*scale2*scale2)
            {
                inv[0] = eb[1]/det0;
                inv[1] = -eb[0]/det0;
                inv[2] = -ea[1]/det0;
                inv[3] = ea[0]/det0;
            }
            else
            {
                degenerate_[j] = 1;   // quality 1 (TetQuality's convention)
                inv[0] = inv[1] = inv[2] = inv[3] = 0;
            }
        }
    }
}


TetMeasures::Worst PlanarCellQualityScan::cellWorst(const std::size_t i, const double* x) const
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

    // Triangle (centre, a, b): F = (fa fb) E0^-1, the tetrahedra's
    // A = diag(F, 1)
    TetMeasures::Worst worst(metric_);
    for (std::size_t j = j0; j < j1; ++j)
    {
        if (degenerate_[j])
        {
            worst.add(-1, -1);
            continue;
        }
        const int a = polygonPoints_[j], b = polygonPoints_[j + 1 < j1 ? j + 1 : j0];
        const double fa[2] = {x[2*a] - c[0], x[2*a + 1] - c[1]};
        const double fb[2] = {x[2*b] - c[0], x[2*b + 1] - c[1]};
        const double* inv = &inverse0_[4*j];
        const double f00 = fa[0]*inv[0] + fb[0]*inv[2], f01 = fa[0]*inv[1] + fb[0]*inv[3];
        const double f10 = fa[1]*inv[0] + fb[1]*inv[2], f11 = fa[1]*inv[1] + fb[1]*inv[3];
        worst.add(f00*f11 - f01*f10, f00*f00 + f01*f01 + f10*f10 + f11*f11 + 1);
    }
    return worst;
}


void PlanarCellQualityScan::measure(const double* p, double* q, const bool wide) const
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
        // the ranked worst's cube roots in SIMD lanes, per block of cells
        WorstBatch finals(metric_, wide);
        constexpr long blockCells = 64;
        #pragma omp for schedule(static, 4)
        for (long b = 0; b < (n + blockCells - 1)/blockCells; ++b)
        {
            for (long i = b*blockCells; i < std::min(n, (b + 1)*blockCells); ++i)
            {
                finals.add(cellWorst(std::size_t(i), x.data()), q + i);
            }
            finals.finish();
        }
    }
}

} // namespace dcprbf
