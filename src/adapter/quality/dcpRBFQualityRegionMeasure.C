/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFQualityRegion, continued: a measurement's summary (the counts, the
    minimum and the mean, the n worst and best cells, the check of the other
    cells whose points can move), in blocks of cells.
\*---------------------------------------------------------------------------*/

#include "dcpRBFQualityRegion.H"
#include "Pstream.H"
#include "dcpRBFVersion.H"

#include <algorithm>
#include <limits>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using Foam::label;
using Foam::scalar;

//- The cells' order: by quality, ties by the reference centre
struct cellOrder
{
    const Foam::scalarField& q;
    const Foam::List<Foam::FixedList<scalar, 3>>& centres;

    Foam::dcpRBFRankedCell ranked(const label i) const
    {
        return Foam::dcpRBFRankedCell(q[i], centres[i]);
    }

    bool lower(const label a, const label b) const
    {
        return q[a] < q[b] || (q[a] == q[b] && ranked(a) < ranked(b));
    }
};


//- Cell i into kept (ascending by before, at most k) where it belongs
template<class Before>
void keep
(
    std::vector<label>& kept,
    const label k,
    const label i,
    const Before& before
)
{
    if (label(kept.size()) < k || before(i, kept.back()))
    {
        kept.insert(std::upper_bound(kept.begin(), kept.end(), i, before), i);
        if (label(kept.size()) > k) kept.pop_back();
    }
}


//- The figures of a block of cells: the number inverted, the least and
//  where it is, the sum, the nLow lowest and nHigh highest (kept sorted)
struct blockFigures
{
    label nInverted = 0;
    scalar least = Foam::GREAT, sum = 0;
    label leastAt = -1;
    std::vector<label> lowestAt, highestAt;
};


//- The figures of the cells [i0, i1), in one pass
void scanBlock
(
    const cellOrder& order,
    const label i0,
    const label i1,
    const label nLow,
    const label nHigh,
    blockFigures& b
)
{
    const Foam::scalarField& q = order.q;
    const auto lower = [&](const label x, const label y) { return order.lower(x, y); };
    const auto higher = [&](const label x, const label y) { return order.lower(y, x); };
    // keep() only for a cell that may enter a full list: at most its last
    // quality (lowest), at least (highest); NaN always
    const auto bound = [&](const std::vector<label>& kept, const label k, const scalar none)
    {
        return k == 0 || label(kept.size()) < k ? none : q[kept.back()];
    };
    constexpr scalar inf = std::numeric_limits<scalar>::infinity();
    scalar low = bound(b.lowestAt, nLow, inf);
    scalar high = bound(b.highestAt, nHigh, -inf);
    // the sum and the least in four interleaved chains (one chain is bound
    // by the additions' latency), in a fixed order: the same on any thread
    // count
    constexpr label U = 4;
    scalar sum[U] = {0, 0, 0, 0};
    scalar least[U] = {Foam::GREAT, Foam::GREAT, Foam::GREAT, Foam::GREAT};
    for (label i = i0; i < i1; i += U)
    {
        for (label u = 0; u < U && i + u < i1; ++u)
        {
            const scalar qi = q[i + u];
            b.nInverted += (qi <= 0);
            least[u] = Foam::min(least[u], qi);
            sum[u] += qi;
            if (nLow > 0 && !(qi > low))
            {
                keep(b.lowestAt, nLow, i + u, lower);
                low = bound(b.lowestAt, nLow, inf);
            }
            if (nHigh > 0 && !(qi < high))
            {
                keep(b.highestAt, nHigh, i + u, higher);
                high = bound(b.highestAt, nHigh, -inf);
            }
        }
    }
    b.sum = (sum[0] + sum[1]) + (sum[2] + sum[3]);
    b.least = Foam::min(Foam::min(least[0], least[1]), Foam::min(least[2], least[3]));
    // the lowest cell (ties: the lower centre), where the least is
    for (label i = i0; i < i1; ++i)
    {
        if (!(q[i] > b.least) && (b.leastAt < 0 || order.lower(i, b.leastAt)))
        {
            b.leastAt = i;
        }
    }
}


//- The blocks' figures merged, in the blocks' order
blockFigures merge
(
    const std::vector<blockFigures>& blocks,
    const cellOrder& order,
    const label nLow,
    const label nHigh
)
{
    const auto lower = [&](const label x, const label y) { return order.lower(x, y); };
    const auto higher = [&](const label x, const label y) { return order.lower(y, x); };
    blockFigures all;
    for (const blockFigures& b : blocks)
    {
        all.nInverted += b.nInverted;
        all.least = Foam::min(all.least, b.least);
        all.sum += b.sum;
        if (b.leastAt >= 0 && (all.leastAt < 0 || order.lower(b.leastAt, all.leastAt)))
        {
            all.leastAt = b.leastAt;
        }
        for (const label i : b.lowestAt) keep(all.lowestAt, nLow, i, lower);
        for (const label i : b.highestAt) keep(all.highestAt, nHigh, i, higher);
    }
    return all;
}


//- The global n first of every processor's ranked cells (each processor's
//  local ones at, in their order), ascending (lowest) or descending
Foam::List<Foam::dcpRBFRankedCell> globalFirst
(
    const cellOrder& order,
    const std::vector<label>& at,
    const label n,
    const bool lowest
)
{
    using Foam::dcpRBFRankedCell;
    std::vector<dcpRBFRankedCell> local;
    for (const label i : at) local.push_back(order.ranked(i));
    const Foam::List<Foam::List<dcpRBFRankedCell>> all
    (
        Foam::dcpRBFCompat::allGather(Foam::dcpRBFCompat::makeList<dcpRBFRankedCell>(local))
    );
    std::vector<dcpRBFRankedCell> cells;
    for (const auto& l : all) cells.insert(cells.end(), l.begin(), l.end());
    if (lowest)
    {
        std::sort(cells.begin(), cells.end());
    }
    else
    {
        std::sort(cells.begin(), cells.end(), [](const dcpRBFRankedCell& a, const dcpRBFRankedCell& b) { return b < a; });
    }
    return Foam::dcpRBFCompat::makeList<dcpRBFRankedCell>
    (
        cells.begin(), cells.begin() + Foam::min(n, label(cells.size()))
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::dcpRBFQualityRegion::summary Foam::dcpRBFQualityRegion::measure
(
    const pointField& p,
    const label n,
    scalarField&& reuse,
    const label nLowest,
    const bool rankBest
) const
{
    scalarField q(std::move(reuse));
    label nMeasured = 0;
    if (nLowest >= 0)
    {
        nMeasured = quality_->computeLowest(p, q, max(n, nLowest));
    }
    else
    {
        quality_->compute(p, q);
        nMeasured = q.size();
    }

    // Per block of cells (fixed, whatever the thread count: the sum and
    // so the mean are the same on any number of threads); then the blocks
    // in order
    const cellOrder order{q, centres_};
    const label nLocal = min(n, q.size());
    const label nBest = rankBest ? nLocal : 0;
    constexpr label blockSize = 16384;
    const label nBlocks = (q.size() + blockSize - 1)/blockSize;
    std::vector<blockFigures> blocks(nBlocks);
    #pragma omp parallel for schedule(static) if(nBlocks > 1)
    for (label bi = 0; bi < nBlocks; ++bi)
    {
        scanBlock
        (
            order, bi*blockSize, min(q.size(), (bi + 1)*blockSize), nLocal,
            nBest, blocks[bi]
        );
    }
    const blockFigures all(merge(blocks, order, nLocal, nBest));

    summary s;
    s.nCells = size();
    s.nInverted = returnReduce(all.nInverted, sumOp<label>());
    s.minQuality = s.nCells ? returnReduce(all.least, minOp<scalar>()) : 1;
    s.meanQuality = s.nCells ? returnReduce(all.sum, sumOp<scalar>())/s.nCells : 1;
    s.worst = globalFirst(order, all.lowestAt, n, true);
    s.best = globalFirst(order, all.highestAt, n, false);

    // The check: the region and the other cells whose points can move
    // (the last of them standing for nAffine_ if any moved affinely)
    label outerInverted = 0;
    scalar outerSum = 0;
    dcpRBFRankedCell lowestHere(GREAT);
    if (all.leastAt >= 0) lowestHere = order.ranked(all.leastAt);
    outer_->accumulate(p, outerInverted, outerSum, lowestHere);
    s.nChecked = nChecked_;
    s.nMeasured = returnReduce(nMeasured, sumOp<label>());
    s.checkedInverted = s.nInverted + returnReduce(outerInverted, sumOp<label>());
    s.checkedMean =
        s.nChecked
      ? returnReduce(all.sum + outerSum, sumOp<scalar>())/s.nChecked : 1;
    s.lowest = globalLowest(lowestHere);
    s.hasLowest = s.lowest.quality() < GREAT;
    s.checkedMin = s.hasLowest ? s.lowest.quality() : 1;
    if (s.nMeasured < s.nCells)
    {
        // bounds in place of qualities (the same on every rank: global
        // counts): no means, no best cells
        s.meanQuality = s.checkedMean = std::numeric_limits<scalar>::quiet_NaN();
        s.best.clear();
    }
    s.quality.transfer(q);
    return s;
}


// ************************************************************************* //
