/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFQualityRegion.H"
#include "dcpRBFScanOrder.H"
#include "PointTree.hpp"
#include "Pstream.H"
#include "emptyPolyPatch.H"
#include "processorPolyPatch.H"
#include "dcpRBFVersion.H"

#include <algorithm>
#include <limits>

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

dcprbf::Points Foam::dcpRBFQualityRegion::checkSources
(
    const polyMesh& mesh,
    const dcpRBFPlaneProjection& projection,
    const pointField& points0,
    const dcpRBFBoundaryPoints& boundaryPoints
)
{
    // This processor's points of the other patches (not candidates)
    std::vector<char> mark(std::size_t(mesh.nPoints()), false);
    DynamicList<FixedList<scalar, 3>> local;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<emptyPolyPatch>(pp) || isA<processorPolyPatch>(pp))
        {
            continue;
        }
        for (const label pointi : pp.meshPoints())
        {
            if
            (
                !mark[pointi]
             && boundaryPoints.kind(pointi) == dcpRBFBoundaryPoints::interiorPoint
            )
            {
                mark[pointi] = true;
                FixedList<scalar, 3> x;
                projection.toCore(points0[pointi], x.data());
                local.append(x);
            }
        }
    }
    List<List<FixedList<scalar, 3>>> all(Pstream::nProcs());
    all[Pstream::myProcNo()].transfer(local);
    dcpRBFCompat::allGatherList(all);

    const dcprbf::Points& candidates = boundaryPoints.points();
    label n = candidates.rows();
    for (const auto& l : all) n += l.size();
    dcprbf::Points sources(n, 3);
    sources.topRows(candidates.rows()) = candidates;
    label row = candidates.rows();
    for (const auto& l : all)
    {
        for (const auto& x : l)
        {
            sources.row(row++) << x[0], x[1], x[2];
        }
    }
    return sources;
}


Foam::dcpRBFRankedCell Foam::dcpRBFQualityRegion::globalLowest
(
    const dcpRBFRankedCell& local
)
{
    // Gathered as lists of scalars: newer versions gather a list of
    // FixedLists (contiguous) with memmove, a -Wclass-memaccess warning; and
    // reduce of a FixedList is elementwise, not the lexicographic order here
    List<scalarList> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = dcpRBFCompat::makeList<scalar>(local);
    dcpRBFCompat::allGatherList(all);
    dcpRBFRankedCell lowest(local);
    for (const scalarList& c : all)
    {
        lowest = std::min(lowest, dcpRBFRankedCell(c));
    }
    return lowest;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFQualityRegion::dcpRBFQualityRegion
(
    const polyMesh& mesh,
    const dcpRBFPlaneProjection& projection,
    const pointField& points0,
    const dcprbf::Points& movingPoints,
    const dcprbf::Points& sources,
    const scalar radius,
    const bool affineBeyond,
    const dcprbf::TetQuality::Metric metric
)
{
    // The cells whose reference centre (the average of their points) is
    // within radius of a moving point: found in parallel (the search
    // stops at the first point within reach)
    const labelListList& cellPoints = mesh.cellPoints();
    std::vector<char> inside(std::size_t(mesh.nCells()), false);
    if (movingPoints.rows() > 0)
    {
        const dcprbf::PointTree tree(movingPoints);
        #pragma omp parallel for schedule(dynamic, 4096)
        for (label celli = 0; celli < mesh.nCells(); ++celli)
        {
            inside[celli] = tree.anyWithin
            (
                dcpRBFScanOrder::centre(cellPoints, projection, points0, celli).data(), radius
            );
        }
    }
    std::vector<label> found;
    for (label celli = 0; celli < mesh.nCells(); ++celli)
    {
        if (inside[celli]) found.push_back(celli);
    }
    cells_ = dcpRBFScanOrder::of(mesh, points0, found);
    centres_.setSize(cells_.size());
    forAll(cells_, i)
    {
        centres_[i] = dcpRBFScanOrder::centre(cellPoints, projection, points0, cells_[i]);
    }
    quality_.reset(new dcpRBFCellQuality(mesh, cells_, points0, metric));

    outer_.reset
    (
        new dcpRBFOuterCells
        (
            mesh, projection, points0, sources, radius, affineBeyond, inside,
            metric
        )
    );
    nChecked_ = returnReduce(cells_.size() + outer_->nChecked(), sumOp<label>());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFQualityRegion::size() const
{
    return returnReduce(cells_.size(), sumOp<label>());
}


Foam::scalarField Foam::dcpRBFQualityRegion::quality(const pointField& p) const
{
    return quality_->compute(p);
}


Foam::labelList Foam::dcpRBFQualityRegion::within
(
    const Eigen::RowVector3d& x,
    const scalar radius
) const
{
    // the centres are a flat array of 3 scalars each, in Morton order
    static_assert
    (
        sizeof(FixedList<scalar, 3>) == 3*sizeof(scalar),
        "centres as a flat array"
    );
    if (!index_)
    {
        index_.reset
        (
            new dcprbf::BlockBoxIndex
            (
                reinterpret_cast<const scalar*>(centres_.cdata()),
                std::size_t(centres_.size())
            )
        );
    }
    // found in ascending positions
    DynamicList<label> positions;
    index_->forEachWithin
    (
        x.data(), radius,
        [&](std::size_t i, double) { positions.append(label(i)); }
    );
    return labelList(std::move(positions));
}


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
    // so the mean are the same on any number of threads): the number
    // inverted, the least, the sum and the n lowest and n highest (kept
    // sorted, in one pass over the block); then the blocks in order
    const auto ranked = [&](const label i)
    {
        return dcpRBFRankedCell(q[i], centres_[i]);
    };
    const auto lower = [&](const label a, const label b)
    {
        return q[a] < q[b] || (q[a] == q[b] && ranked(a) < ranked(b));
    };
    const auto higher = [&](const label a, const label b) { return lower(b, a); };
    const label nLocal = min(n, q.size());
    const label nBest = rankBest ? nLocal : 0;
    const auto keep = [](std::vector<label>& kept, const label k, const label i, const auto& before)
    {
        if (label(kept.size()) < k || before(i, kept.back()))
        {
            kept.insert(std::upper_bound(kept.begin(), kept.end(), i, before), i);
            if (label(kept.size()) > k) kept.pop_back();
        }
    };
    struct block
    {
        label nInverted = 0;
        scalar least = GREAT, sum = 0;
        label leastAt = -1;
        std::vector<label> lowestAt, highestAt;
    };
    constexpr label blockSize = 16384;
    const label nBlocks = (q.size() + blockSize - 1)/blockSize;
    std::vector<block> blocks(nBlocks);
    #pragma omp parallel for schedule(static) if(nBlocks > 1)
    for (label bi = 0; bi < nBlocks; ++bi)
    {
        block& b = blocks[bi];
        const label i1 = min(q.size(), (bi + 1)*blockSize);
        // keep() only for a cell that may enter a full list: at most its
        // last quality (lowest), at least (highest); NaN always
        const auto bound = [&](const std::vector<label>& kept, const label k, const scalar none)
        {
            return k == 0 || label(kept.size()) < k ? none : q[kept.back()];
        };
        constexpr scalar inf = std::numeric_limits<scalar>::infinity();
        scalar low = bound(b.lowestAt, nLocal, inf);
        scalar high = bound(b.highestAt, nBest, -inf);
        // the sum and the least in four interleaved chains (one chain is
        // bound by the additions' latency), in a fixed order: the same on
        // any thread count
        constexpr label U = 4;
        scalar sum[U] = {0, 0, 0, 0}, least[U] = {GREAT, GREAT, GREAT, GREAT};
        for (label i = bi*blockSize; i < i1; i += U)
        {
            for (label u = 0; u < U && i + u < i1; ++u)
            {
                const scalar qi = q[i + u];
                b.nInverted += (qi <= 0);
                least[u] = min(least[u], qi);
                sum[u] += qi;
                if (nLocal > 0 && !(qi > low))
                {
                    keep(b.lowestAt, nLocal, i + u, lower);
                    low = bound(b.lowestAt, nLocal, inf);
                }
                if (nBest > 0 && !(qi < high))
                {
                    keep(b.highestAt, nBest, i + u, higher);
                    high = bound(b.highestAt, nBest, -inf);
                }
            }
        }
        b.sum = (sum[0] + sum[1]) + (sum[2] + sum[3]);
        b.least = min(min(least[0], least[1]), min(least[2], least[3]));
        // the lowest cell (ties: the lower centre), where the least is
        for (label i = bi*blockSize; i < i1; ++i)
        {
            if (!(q[i] > b.least) && (b.leastAt < 0 || lower(i, b.leastAt)))
            {
                b.leastAt = i;
            }
        }
    }
    label nInverted = 0;
    scalar least = GREAT, sum = 0;
    label leastAt = -1;
    std::vector<label> lowestAt, highestAt;
    for (const block& b : blocks)
    {
        nInverted += b.nInverted;
        least = min(least, b.least);
        sum += b.sum;
        if (b.leastAt >= 0 && (leastAt < 0 || lower(b.leastAt, leastAt)))
        {
            leastAt = b.leastAt;
        }
        for (const label i : b.lowestAt) keep(lowestAt, nLocal, i, lower);
        for (const label i : b.highestAt) keep(highestAt, nBest, i, higher);
    }

    summary s;
    s.nCells = size();
    s.nInverted = returnReduce(nInverted, sumOp<label>());
    s.minQuality = s.nCells ? returnReduce(least, minOp<scalar>()) : 1;
    s.meanQuality = s.nCells ? returnReduce(sum, sumOp<scalar>())/s.nCells : 1;

    // The global n worst and n best
    std::vector<dcpRBFRankedCell> lowest, highest;
    for (const label i : lowestAt) lowest.push_back(ranked(i));
    for (const label i : highestAt) highest.push_back(ranked(i));

    List<List<dcpRBFRankedCell>> worstAll(Pstream::nProcs()), bestAll(Pstream::nProcs());
    worstAll[Pstream::myProcNo()] = dcpRBFCompat::makeList<dcpRBFRankedCell>(lowest);
    bestAll[Pstream::myProcNo()] = dcpRBFCompat::makeList<dcpRBFRankedCell>(highest);
    dcpRBFCompat::allGatherList(worstAll);
    dcpRBFCompat::allGatherList(bestAll);

    std::vector<dcpRBFRankedCell> worst, best;
    for (const auto& l : worstAll) worst.insert(worst.end(), l.begin(), l.end());
    for (const auto& l : bestAll) best.insert(best.end(), l.begin(), l.end());
    std::sort(worst.begin(), worst.end());
    std::sort(best.begin(), best.end(), [](const dcpRBFRankedCell& a, const dcpRBFRankedCell& b) { return b < a; });

    s.worst = dcpRBFCompat::makeList<dcpRBFRankedCell>(worst.begin(), worst.begin() + min(n, label(worst.size())));
    s.best = dcpRBFCompat::makeList<dcpRBFRankedCell>(best.begin(), best.begin() + min(n, label(best.size())));

    // The check: the region and the other cells whose points can move
    // (the last of them standing for nAffine_ if any moved affinely)
    label outerInverted = 0;
    scalar outerSum = 0;
    dcpRBFRankedCell lowestHere(GREAT);
    if (leastAt >= 0) lowestHere = ranked(leastAt);
    outer_->accumulate(p, outerInverted, outerSum, lowestHere);
    s.nChecked = nChecked_;
    s.nMeasured = returnReduce(nMeasured, sumOp<label>());
    s.checkedInverted = s.nInverted + returnReduce(outerInverted, sumOp<label>());
    s.checkedMean =
        s.nChecked
      ? returnReduce(sum + outerSum, sumOp<scalar>())/s.nChecked : 1;
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
