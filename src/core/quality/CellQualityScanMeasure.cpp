// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// CellQualityScan: the measurement (the construction is in CellQualityScan.cpp).
#include "CellQualityScan.hpp"
#include "TetMeasures.hpp"

#include <omp.h>

#include <algorithm>
#include <memory>

namespace dcprbf
{

namespace
{

//- A tetrahedral cell of vertices v (CellShapes' order) into position t
//  of batch: its edges from v[0], reference (points x0) and current (x)
inline void setTetrahedron
(
    const int* v,
    const double* x0,
    const double* x,
    detail::TetBatch& batch,
    const std::size_t t
)
{
    double e[3][3], f[3][3];
    for (int k = 0; k < 3; ++k)
    {
        const std::size_t a = 3*std::size_t(v[k + 1]), o = 3*std::size_t(v[0]);
        for (int d = 0; d < 3; ++d)
        {
            e[k][d] = x0[a + d] - x0[o + d];
            f[k][d] = x[a + d] - x[o + d];
        }
    }
    batch.set(t, e[0], e[1], e[2], f[0], f[1], f[2]);
}


//- The worst tetrahedron of the cell at position p of a measured
//  detail::PrismBatch (NT = 18) or detail::HexBatch (24): the batch's own
//  where exact, else its NT tetrahedra ranked here
template<int NT, class Batch>
inline detail::TetMeasures::Worst laneCellWorst
(
    const Batch& batch,
    const std::size_t p,
    const TetQuality::Metric metric
)
{
    detail::TetMeasures::Worst worst(metric);
    if (!batch.exact(p))
    {
        for (int t = 0; t < NT; ++t)
        {
            worst.add(batch.tetJ(p, t), batch.tetA2(p, t));
        }
    }
    else
    {
        worst = batch.worst(p, metric);
    }
    return worst;
}


//- The worst of the tetrahedra t0 .. t1 - 1 of a measured detail::TetBatch
//  (a cell's)
inline detail::TetMeasures::Worst tetsWorst
(
    const detail::TetBatch& tets,
    const std::size_t t0,
    const std::size_t t1,
    const TetQuality::Metric metric
)
{
    detail::TetMeasures::Worst worst(metric);
    for (std::size_t t = t0; t < t1; ++t)
    {
        worst.add(tets.J(t), tets.a2(t), tets.key(t));
    }
    return worst;
}

} // namespace


std::size_t CellQualityScan::tetCount(const std::size_t g) const
{
    return faceStart_[cellStart_[g + 1]] - faceStart_[cellStart_[g]];
}


void CellQualityScan::addTets
(
    const std::size_t g,
    const double* x,
    detail::TetBatch& batch,
    std::size_t t,
    std::vector<double>& buf
) const
{
    const double* x0 = points0_.data();
    const std::size_t k0 = cellStart_[g], k1 = cellStart_[g + 1];
    buf.resize(3*(k1 - k0));
    double cc[3] = {0, 0, 0};
    for (std::size_t k = k0; k < k1; ++k)
    {
        double* fc = &buf[3*(k - k0)];
        fc[0] = fc[1] = fc[2] = 0;
        for (std::size_t j = faceStart_[k]; j < faceStart_[k + 1]; ++j)
        {
            const double* y = x + 3*std::size_t(facePoints_[j]);
            fc[0] += y[0]; fc[1] += y[1]; fc[2] += y[2];
        }
        const double n = double(faceStart_[k + 1] - faceStart_[k]);
        for (int d = 0; d < 3; ++d)
        {
            fc[d] /= n;
            cc[d] += fc[d];
        }
    }
    for (int d = 0; d < 3; ++d) cc[d] /= double(k1 - k0);

    // The tetrahedra of face k: (cc, fc, a_j, a_j+1), edges from cc
    const double* cc0 = &cellCentres0_[3*g];
    for (std::size_t k = k0; k < k1; ++k)
    {
        const double* fc0 = &faceCentres0_[3*k];
        const double* fc = &buf[3*(k - k0)];
        const std::size_t j0 = faceStart_[k], n = faceStart_[k + 1] - j0;
        double e0[3], f0[3];
        for (int d = 0; d < 3; ++d)
        {
            e0[d] = fc0[d] - cc0[d];
            f0[d] = fc[d] - cc[d];
        }
        for (std::size_t j = 0; j < n; ++j, ++t)
        {
            const std::size_t a = 3*std::size_t(facePoints_[j0 + j]);
            const std::size_t b = 3*std::size_t(facePoints_[j0 + (j + 1 < n ? j + 1 : 0)]);
            double ea[3], eb[3], fa[3], fb[3];
            for (int d = 0; d < 3; ++d)
            {
                ea[d] = x0[a + d] - cc0[d];
                eb[d] = x0[b + d] - cc0[d];
                fa[d] = x[a + d] - cc[d];
                fb[d] = x[b + d] - cc[d];
            }
            batch.set(t, e0, ea, eb, f0, fa, fb);
        }
    }
}


void CellQualityScan::placeBlock
(
    const int* at,
    const std::size_t m,
    Scratch& s
) const
{
    std::size_t nTets = 0, nPrisms = 0, nHexes = 0;
    for (std::size_t c = 0; c < m; ++c)
    {
        const std::size_t i = std::size_t(at[c]);
        if (kind_[i] == prism)
        {
            s.first[c] = nPrisms++;
        }
        else if (kind_[i] == hexahedron)
        {
            s.first[c] = nHexes++;
        }
        else
        {
            s.first[c] = nTets;
            nTets += kind_[i] == tetrahedron ? 1 : tetCount(std::size_t(slot_[i]));
        }
    }
    s.tets.resize(nTets);
    s.prisms.resize(nPrisms);
    s.hexes.resize(nHexes);
}


void CellQualityScan::fillBlock
(
    const int* at,
    const std::size_t m,
    const double* x,
    Scratch& s
) const
{
    const double* x0 = points0_.data();
    for (std::size_t c = 0; c < m; ++c)
    {
        const std::size_t i = std::size_t(at[c]);
        if (kind_[i] == prism)
        {
            s.prisms.set(s.first[c], x0, x, &vertices_[std::size_t(slot_[i])]);
        }
        else if (kind_[i] == hexahedron)
        {
            s.hexes.set(s.first[c], x0, x, &vertices_[std::size_t(slot_[i])]);
        }
        else if (kind_[i] == tetrahedron)
        {
            setTetrahedron(&vertices_[std::size_t(slot_[i])], x0, x, s.tets, s.first[c]);
        }
        else
        {
            addTets(std::size_t(slot_[i]), x, s.tets, s.first[c], s.buf);
        }
    }
}


void CellQualityScan::measureBlock
(
    const int* at,
    const std::size_t m,
    const double* x,
    Scratch& s,
    double* q
) const
{
    // The prisms into a detail::PrismBatch, the hexahedra into a
    // detail::HexBatch, the tetrahedra of the others into a
    // detail::TetBatch (a tetrahedral cell: one, with its own A: every
    // tetrahedron of its decomposition is an affine image of it)
    placeBlock(at, m, s);
    fillBlock(at, m, x, s);

    // Measured in SIMD lanes; each cell's worst (detail::TetMeasures::Worst), the
    // qualities in SIMD lanes again (detail::WorstBatch)
    if (s.tets.size()) s.tets.measure(metric_, s.finals.wide());
    if (s.prisms.size()) s.prisms.measure(metric_, s.finals.wide());
    if (s.hexes.size()) s.hexes.measure(metric_, s.finals.wide());
    for (std::size_t c = 0; c < m; ++c)
    {
        const std::size_t i = std::size_t(at[c]), p = s.first[c];
        const detail::TetMeasures::Worst worst =
            kind_[i] == hexahedron ? laneCellWorst<24>(s.hexes, p, metric_)
          : kind_[i] == prism ? laneCellWorst<18>(s.prisms, p, metric_)
          : tetsWorst
            (
                s.tets,
                p,
                p + (kind_[i] == tetrahedron ? 1 : tetCount(std::size_t(slot_[i]))),
                metric_
            );
        s.finals.add(worst, &q[order_[i]]);
    }
    s.finals.finish();
}


const double* CellQualityScan::gather(const double* p, const bool parallel) const
{
    const long nPoints = long(pointIds_.size());
    // filled in parallel below: not value-initialised (a serial pass);
    // allocated once (fresh pages each step cost page faults)
    if (!compact_)
    {
        compact_.reset(new double[3*pointIds_.size()]);
    }
    double* const x = compact_.get();
    #pragma omp parallel for schedule(static) if(parallel)
    for (long i = 0; i < nPoints; ++i)
    {
        const double* y = p + 3*std::size_t(pointIds_[i]);
        x[3*i] = y[0];
        x[3*i + 1] = y[1];
        x[3*i + 2] = y[2];
    }
    return x;
}


CellQualityScan::Scratch& CellQualityScan::scratch(const bool wide) const
{
    std::unique_ptr<Scratch>& slot = scratch_[std::size_t(omp_get_thread_num())];
    if (!slot || slot->finals.wide() != wide)
    {
        slot.reset(new Scratch(metric_, wide));
    }
    return *slot;
}


void CellQualityScan::measureCells
(
    const std::vector<int>& at,
    const double* x,
    double* q,
    const bool wide
) const
{
    const std::size_t n = at.size();
    const long nBlocks = long((n + blockCells - 1)/blockCells);
    const bool parallel = n >= minParallelCells;
    const std::size_t nThreads = parallel ? std::size_t(omp_get_max_threads()) : 1;
    if (scratch_.size() < nThreads)
    {
        scratch_.resize(nThreads);
    }
    // threads for a scan worth waking them (a sleeping thread takes ~0.1 ms)
    #pragma omp parallel if(parallel)
    {
        Scratch& s = scratch(wide);
        #pragma omp for schedule(static, 8)
        for (long b = 0; b < nBlocks; ++b)
        {
            const std::size_t i0 = std::size_t(b)*blockCells;
            measureBlock(&at[i0], std::min(blockCells, n - i0), x, s, q);
        }
    }
}


void CellQualityScan::measure(const double* p, double* q, const bool wide) const
{
    // every cell, in the order stored
    if (every_.size() != size())
    {
        every_.resize(size());
        for (std::size_t i = 0; i < every_.size(); ++i) every_[i] = int(i);
    }
    measureCells(every_, gather(p, size() >= minParallelCells), q, wide);
}

} // namespace dcprbf
