/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFQualityRegion.H"
#include "PointTree.hpp"
#include "Pstream.H"

#include <algorithm>


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFQualityRegion::dcpRBFQualityRegion
(
    const polyMesh& mesh,
    const dcpRBFPlaneProjection& projection,
    const pointField& points0,
    const dcprbf::Points& movingPoints,
    const scalar radius,
    const dcprbf::TetQuality::Metric metric
)
{
    if (movingPoints.rows() == 0)
    {
        quality_.reset(new dcpRBFCellQuality(mesh, cells_, points0, metric));
        return;
    }
    const dcprbf::PointTree tree(movingPoints);
    DynamicList<label> cells;
    DynamicList<FixedList<scalar, 3>> centres;
    forAll(mesh.cells(), celli)
    {
        // reference centre: average of the cell's points
        const labelList& cp = mesh.cellPoints()[celli];
        vector c(Zero);
        for (const label pi : cp) c += points0[pi];
        c /= cp.size();

        FixedList<scalar, 3> x;
        projection.toCore(c, x.data());
        scalar d2 = 0;
        tree.nearest(x.data(), d2);
        if (d2 < sqr(radius))
        {
            cells.append(celli);
            centres.append(x);
        }
    }
    cells_.transfer(cells);
    centres_.transfer(centres);
    quality_.reset(new dcpRBFCellQuality(mesh, cells_, points0, metric));
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
    DynamicList<label> positions;
    if (!tree_ && centres_.size())
    {
        dcprbf::Points c(centres_.size(), 3);
        forAll(centres_, i)
        {
            c.row(i) << centres_[i][0], centres_[i][1], centres_[i][2];
        }
        tree_.reset(new dcprbf::PointTree(c));
    }
    if (tree_ && tree_->size())
    {
        tree_->forEachWithin
        (
            x.data(), radius,
            [&](std::size_t i, double) { positions.append(label(i)); }
        );
    }
    labelList l(std::move(positions));
    Foam::sort(l);
    return l;
}


Foam::dcpRBFQualityRegion::summary Foam::dcpRBFQualityRegion::measure
(
    const pointField& p,
    const label n
) const
{
    scalarField q(quality(p));

    summary s;
    s.nCells = size();
    s.nInverted = returnReduce
    (
        label(std::count_if(q.begin(), q.end(), [](scalar x) { return x <= 0; })),
        sumOp<label>()
    );
    s.minQuality = s.nCells ? gMin(q) : 1;
    s.meanQuality = s.nCells ? gSum(q)/s.nCells : 1;

    // Local candidates (the n lowest and n highest, in one pass over the
    // positions, kept sorted), then the global n worst and n best
    const auto ranked = [&](const label i)
    {
        return rankedCell({q[i], centres_[i][0], centres_[i][1], centres_[i][2]});
    };
    const auto lower = [&](const label a, const label b)
    {
        return q[a] < q[b] || (q[a] == q[b] && ranked(a) < ranked(b));
    };
    const auto higher = [&](const label a, const label b) { return lower(b, a); };
    const label nLocal = min(n, q.size());
    std::vector<label> lowestAt, highestAt;
    const auto keep = [nLocal](std::vector<label>& kept, const label i, const auto& before)
    {
        if (label(kept.size()) < nLocal || before(i, kept.back()))
        {
            kept.insert(std::upper_bound(kept.begin(), kept.end(), i, before), i);
            if (label(kept.size()) > nLocal) kept.pop_back();
        }
    };
    for (label i = 0; nLocal > 0 && i < q.size(); ++i)
    {
        keep(lowestAt, i, lower);
        keep(highestAt, i, higher);
    }
    std::vector<rankedCell> lowest, highest;
    for (const label i : lowestAt) lowest.push_back(ranked(i));
    for (const label i : highestAt) highest.push_back(ranked(i));

    List<List<rankedCell>> worstAll(Pstream::nProcs()), bestAll(Pstream::nProcs());
    worstAll[Pstream::myProcNo()] = List<rankedCell>(lowest.begin(), lowest.end());
    bestAll[Pstream::myProcNo()] = List<rankedCell>(highest.begin(), highest.end());
    Pstream::gatherList(worstAll);
    Pstream::scatterList(worstAll);
    Pstream::gatherList(bestAll);
    Pstream::scatterList(bestAll);

    std::vector<rankedCell> worst, best;
    for (const auto& l : worstAll) worst.insert(worst.end(), l.begin(), l.end());
    for (const auto& l : bestAll) best.insert(best.end(), l.begin(), l.end());
    std::sort(worst.begin(), worst.end());
    std::sort(best.begin(), best.end(), [](const rankedCell& a, const rankedCell& b) { return b < a; });

    s.worst = List<rankedCell>(worst.begin(), worst.begin() + min(n, label(worst.size())));
    s.best = List<rankedCell>(best.begin(), best.begin() + min(n, label(best.size())));
    s.quality.transfer(q);
    return s;
}


// ************************************************************************* //
