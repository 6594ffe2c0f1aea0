/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFTrialWindow.H"
#include "SmallestValues.hpp"
#include "dcpRBFVersion.H"
#include "syncTools.H"

#include <algorithm>
#include <iterator>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::dcpRBFTrialWindow::lowest
(
    const scalarField& q,
    const label n
)
{
    // the n lowest here (in no order), then the global n-th lowest of all
    const label nLocal = max(label(0), min(n, q.size()));
    const std::vector<scalar> lowestHere
    (
        dcprbf::smallestValues(q.cdata(), std::size_t(q.size()), std::size_t(nLocal))
    );

    const List<scalarList> all
    (
        dcpRBFCompat::allGather(dcpRBFCompat::makeList<scalar>(lowestHere))
    );
    std::vector<scalar> merged;
    for (const scalarList& l : all)
    {
        merged.insert(merged.end(), l.begin(), l.end());
    }
    if (merged.empty() || n <= 0)
    {
        return labelList();
    }
    const std::size_t k = std::min(std::size_t(n), merged.size()) - 1;
    std::nth_element(merged.begin(), merged.begin() + k, merged.end());
    const scalar threshold = merged[k];

    DynamicList<label> positions(nLocal);
    forAll(q, i)
    {
        if (q[i] <= threshold)
        {
            positions.append(i);
        }
    }
    return labelList(std::move(positions));
}


void Foam::dcpRBFTrialWindow::append(labelList&& positions)
{
    labelList merged(positions_.size() + positions.size());
    std::merge
    (
        positions_.begin(), positions_.end(), positions.begin(), positions.end(),
        merged.begin()
    );
    positions_.transfer(merged);
    // the region's classified cells copied (flat scan and 2D polygons)
    scans_.append(new dcpRBFCellQuality(region_.cellQuality(), positions, points0_));
    // the new cells' points not yet in the window (from the scan's list of
    // the points it reads, else from the mesh's faces)
    const label nBefore = points_.size();
    const auto mark = [&](const label pointi)
    {
        if (marked_.set(pointi))
        {
            points_.append(pointi);
        }
    };
    if (const std::vector<int>* ids = scans_.last().pointIds())
    {
        for (const int pointi : *ids)
        {
            mark(pointi);
        }
    }
    else
    {
        const cellList& cells = mesh_.cells();
        const faceList& faces = mesh_.faces();
        for (const label i : positions)
        {
            for (const label facei : cells[region_.cells()[i]])
            {
                for (const label pointi : faces[facei])
                {
                    mark(pointi);
                }
            }
        }
    }
    nAdded_ = points_.size() - nBefore;
    // (ascending: the points' values read in order)
    std::sort(points_.begin() + nBefore, points_.end());
    chunks_.append(std::move(positions));
}


Foam::dcpRBFRankedCell Foam::dcpRBFTrialWindow::localWorst
(
    const dcpRBFCellQuality& quality,
    const labelUList& positions,
    const pointField& p
) const
{
    // none here: above every quality
    const scalarField q(quality.compute(p));
    const List<FixedList<scalar, 3>>& centres = region_.centres();
    dcpRBFRankedCell w(VGREAT);
    forAll(q, i)
    {
        w = std::min(w, dcpRBFRankedCell(q[i], centres[positions[i]]));
    }
    return w;
}


Foam::dcpRBFRankedCell Foam::dcpRBFTrialWindow::globalWorst
(
    const dcpRBFRankedCell& local
)
{
    dcpRBFRankedCell w(dcpRBFQualityRegion::globalLowest(local));
    if (w.quality() == VGREAT)
    {
        w.quality() = 1;
    }
    return w;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFTrialWindow::dcpRBFTrialWindow
(
    const polyMesh& mesh,
    const dcpRBFQualityRegion& region,
    const scalarField& q,
    const label n,
    const pointField& points0
)
:
    mesh_(mesh),
    region_(region),
    points0_(points0),
    marked_(mesh.nPoints())
{
    append(lowest(q, n));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFTrialWindow::nGlobalPoints
(
    const bitSet& masterPoints
) const
{
    if (!Pstream::parRun())
    {
        return points_.size();
    }
    // a point in any processor's list, counted by its master
    // (labels: OpenFOAM's exchange of bools trips GCC's allocation-size
    // warning, an error in CI)
    labelList in(mesh_.nPoints(), 0);
    for (const label pointi : points_)
    {
        in[pointi] = 1;
    }
    syncTools::syncPointList(mesh_, in, maxEqOp<label>(), label(0));
    label n = 0;
    forAll(in, pointi)
    {
        if (in[pointi] && masterPoints.test(pointi))
        {
            ++n;
        }
    }
    return returnReduce(n, sumOp<label>());
}


Foam::label Foam::dcpRBFTrialWindow::size() const
{
    return returnReduce(positions_.size(), sumOp<label>());
}


void Foam::dcpRBFTrialWindow::add
(
    const Eigen::RowVector3d& x,
    const scalar radius
)
{
    const labelList near(region_.within(x, radius));
    std::vector<label> added;
    std::set_difference
    (
        near.begin(), near.end(), positions_.begin(), positions_.end(),
        std::back_inserter(added)
    );
    append(dcpRBFCompat::makeList<label>(added));
}


Foam::dcpRBFRankedCell
Foam::dcpRBFTrialWindow::worstAdded(const pointField& p) const
{
    return globalWorst(localWorst(scans_.last(), chunks_.last(), p));
}


Foam::dcpRBFRankedCell
Foam::dcpRBFTrialWindow::worst(const pointField& p) const
{
    // every chunk here, then one exchange
    dcpRBFRankedCell w(VGREAT);
    forAll(scans_, i)
    {
        w = std::min(w, localWorst(scans_[i], chunks_[i], p));
    }
    return globalWorst(w);
}

Foam::scalar Foam::dcpRBFTrialWindow::sum(const pointField& p) const
{
    scalar s = 0;
    for (const dcpRBFCellQuality& quality : scans_)
    {
        s += Foam::sum(quality.compute(p));
    }
    return returnReduce(s, sumOp<scalar>());
}

// ************************************************************************* //
