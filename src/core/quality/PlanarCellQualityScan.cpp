// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "PlanarCellQualityScan.hpp"
#include "ScratchNumbering.hpp"
#include "PlanarMapBatch.hpp"
#include "WorstBatch.hpp"
#include "TetMeasures.hpp"

#include <algorithm>
#include <memory>
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
    for (std::size_t i = 0; i + 1 < polygonStart_.size(); ++i)
    {
        if (polygonStart_[i + 1] < polygonStart_[i] + 3)
        {
            throw std::invalid_argument("PlanarCellQualityScan: polygon size");
        }
    }
    int maxIndex = -1;
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
    setUp(points0);
}


PlanarCellQualityScan::PlanarCellQualityScan
(
    const PlanarCellQualityScan& from,
    const std::vector<int>& cells,
    const double* points0
)
:
    polygonStart_(1, 0),
    axis0_(from.axis0_),
    axis1_(from.axis1_),
    metric_(from.metric_)
{
    // from's points renumbered in order of use (through from's scratch)
    ScratchNumbering local(from.subsetPoint_, from.pointIds_.size());
    for (const int c : cells)
    {
        if (c < 0 || std::size_t(c) >= from.size())
        {
            throw std::invalid_argument("PlanarCellQualityScan: a subset's cell index");
        }
        for (std::size_t j = from.polygonStart_[c]; j < from.polygonStart_[c + 1]; ++j)
        {
            polygonPoints_.push_back(local(from.polygonPoints_[j], [&](const int p)
            {
                pointIds_.push_back(from.pointIds_[std::size_t(p)]);
            }));
        }
        polygonStart_.push_back(polygonPoints_.size());
    }
    setUp(points0);
}


void PlanarCellQualityScan::setUp(const double* points0)
{
    // Per map the inverse of its reference edges E0 = (ea, eb), once: a
    // measurement needs F = E E0^-1 only. A triangle: one map, its own
    // (ea, eb = b - a, c - a; each triangle of the decomposition (centre,
    // edge) is an affine image of it: the same F); a polygon of n >= 4
    // points: n maps, the triangles (centre c, a, b), ea = a - c, eb = b - c
    const auto at = [&](const int k, const int d)
    {
        return points0[3*std::size_t(pointIds_[std::size_t(k)]) + (d ? axis1_ : axis0_)];
    };
    // The inverse of (ea, eb) into inv (row major), or degenerate
    const auto inverse = [](const double* ea, const double* eb, double* inv)
    {
        const double det0 = ea[0]*eb[1] - ea[1]*eb[0];
        const double scale2 = std::max(ea[0]*ea[0] + ea[1]*ea[1], eb[0]*eb[0] + eb[1]*eb[1]);
        if (det0*det0 > 1e-28*scale2*scale2)
        {
            inv[0] = eb[1]/det0;
            inv[1] = -eb[0]/det0;
            inv[2] = -ea[1]/det0;
            inv[3] = ea[0]/det0;
            return false;
        }
        std::fill(inv, inv + 4, 0.0);
        return true;   // quality 1 (TetQuality's convention)
    };
    mapStart_.assign(1, 0);
    double inv[16], one[4];
    bool degenerate[4];
    for (std::size_t i = 0; i < size(); ++i)
    {
        const std::size_t j0 = polygonStart_[i], j1 = polygonStart_[i + 1];
        if (j1 - j0 == 3)
        {
            const int a = polygonPoints_[j0], b = polygonPoints_[j0 + 1];
            const int c = polygonPoints_[j0 + 2];
            const double ea[2] = {at(b, 0) - at(a, 0), at(b, 1) - at(a, 1)};
            const double eb[2] = {at(c, 0) - at(a, 0), at(c, 1) - at(a, 1)};
            degenerate[0] = inverse(ea, eb, one);
            triangles_.add(i, &polygonPoints_[j0], one, degenerate);
            continue;
        }
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
            const bool flat = inverse(ea, eb, one);
            if (j1 - j0 == 4)
            {
                degenerate[j - j0] = flat;
                std::copy(one, one + 4, inv + 4*(j - j0));
            }
            else
            {
                degenerate_.push_back(flat);
                inverse0_.insert(inverse0_.end(), one, one + 4);
            }
        }
        if (j1 - j0 == 4)
        {
            quads_.add(i, &polygonPoints_[j0], inv, degenerate);
        }
        else
        {
            otherCells_.push_back(i);
            mapStart_.push_back(degenerate_.size());
        }
    }
    triangles_.finishAdding();
    quads_.finishAdding();
}


void PlanarCellQualityScan::addMaps
(
    const std::size_t k,
    const double* x,
    detail::PlanarMapBatch& batch,
    std::size_t t
) const
{
    const std::size_t i = otherCells_[k];
    const std::size_t j0 = polygonStart_[i], j1 = polygonStart_[i + 1];
    std::size_t m = mapStart_[k];
    const double n = double(j1 - j0);
    double c[2] = {0, 0};
    for (std::size_t j = j0; j < j1; ++j)
    {
        c[0] += x[2*polygonPoints_[j]];
        c[1] += x[2*polygonPoints_[j] + 1];
    }
    c[0] /= n;
    c[1] /= n;
    for (std::size_t j = j0; j < j1; ++j, ++m, ++t)
    {
        const int a = polygonPoints_[j], b = polygonPoints_[j + 1 < j1 ? j + 1 : j0];
        batch.set
        (
            t, x[2*a] - c[0], x[2*a + 1] - c[1], x[2*b] - c[0], x[2*b + 1] - c[1],
            &inverse0_[4*m], degenerate_[m]
        );
    }
}


void PlanarCellQualityScan::measure(const double* p, double* q, const bool wide) const
{
    const long nPoints = long(pointIds_.size());
    // filled in parallel below: not value-initialised (a serial pass);
    // allocated once (fresh pages each step cost page faults)
    if (!compact_)
    {
        compact_.reset(new double[2*pointIds_.size()]);
    }
    double* const x = compact_.get();
    // threads for a scan worth waking them (a sleeping thread takes ~0.1 ms)
    #pragma omp parallel if(size() >= minParallelCells)
    {
        #pragma omp for schedule(static)
        for (long i = 0; i < nPoints; ++i)
        {
            x[2*i] = p[3*std::size_t(pointIds_[i]) + axis0_];
            x[2*i + 1] = p[3*std::size_t(pointIds_[i]) + axis1_];
        }
        // The triangles and quadrilaterals (detail::PlanarPolygonBatch: one cell
        // per SIMD lane); per block of the other cells: the maps into a
        // detail::PlanarMapBatch (SIMD), each cell's worst, the ranked worst's
        // qualities in SIMD lanes
        triangles_.measure(x, q, metric_, wide);
        quads_.measure(x, q, metric_, wide);
        detail::PlanarMapBatch maps;
        detail::WorstBatch finals(metric_, wide);
        constexpr long blockCells = 64;
        const long n = long(otherCells_.size());
        #pragma omp for schedule(static, 4)
        for (long b = 0; b < (n + blockCells - 1)/blockCells; ++b)
        {
            const std::size_t k0 = std::size_t(b*blockCells);
            const std::size_t k1 = std::size_t(std::min(n, (b + 1)*blockCells));
            const std::size_t m0 = mapStart_[k0];
            maps.resize(mapStart_[k1] - m0);
            for (std::size_t k = k0; k < k1; ++k)
            {
                addMaps(k, x, maps, mapStart_[k] - m0);
            }
            maps.measure(metric_, wide);
            for (std::size_t k = k0; k < k1; ++k)
            {
                detail::TetMeasures::Worst worst(metric_);
                for (std::size_t t = mapStart_[k] - m0; t < mapStart_[k + 1] - m0; ++t)
                {
                    worst.add(maps.J(t), maps.a2(t), maps.key(t));
                }
                finals.add(worst, q + otherCells_[k]);
            }
            finals.finish();
        }
    }
}

} // namespace dcprbf
