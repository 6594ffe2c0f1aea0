/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFBoundaryPoints.H"
#include "Pstream.H"
#include "syncTools.H"
#include "dcpRBFVersion.H"
#include "PointTree.hpp"
#include "PointSetChecks.hpp"

#include <algorithm>
#include <numeric>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFBoundaryPoints::markPoints
(
    const polyMesh& mesh,
    const labelList& movingPatchIDs,
    const labelList& staticPatchIDs,
    const dcpRBFRegion& region
)
{
    labelList kind(mesh.nPoints(), label(interiorPoint));
    for (const label patchi : staticPatchIDs)
    {
        for (const label pointi : mesh.boundaryMesh()[patchi].meshPoints())
        {
            kind[pointi] = staticPoint;
        }
    }
    for (const label patchi : movingPatchIDs)
    {
        for (const label pointi : mesh.boundaryMesh()[patchi].meshPoints())
        {
            kind[pointi] = movingPoint;
        }
    }
    // A processor may hold a patch point without any of the patch's faces
    syncTools::syncPointList(mesh, kind, maxEqOp<label>(), label(interiorPoint));
    // (the region's membership is synchronised already)
    forAll(kind, pointi)
    {
        if (!region.point(pointi))
        {
            kind[pointi] = outsidePoint;
        }
        else if (region.border(pointi) && kind[pointi] != movingPoint)
        {
            kind[pointi] = staticPoint;
        }
    }
    kind_.setSize(kind.size());
    forAll(kind, pointi)
    {
        kind_[pointi] = pointKind(kind[pointi]);
    }
}


void Foam::dcpRBFBoundaryPoints::checkDistinct
(
    const polyMesh& mesh,
    const labelList& movingPatchIDs,
    const labelList& staticPatchIDs
) const
{
    // (the core's test of a control set, PointSetChecks::checkDistinct)
    Eigen::Index i = 0, j = 0;
    const double ext = dcprbf::PointSetChecks::extent(points_);
    if
    (
        points_.rows() < 2 || ext == 0
     || !dcprbf::PointTree::findCoincident(points_, 1e-10*ext, i, j)
    )
    {
        return;
    }
    // the patches of the two points, from the processors that hold them
    const auto patchesOf = [&](const Eigen::Index g)
    {
        wordList names;
        const globalIndex numbering(holders());
        forAll(localPoints_, l)
        {
            if (concatToGlobal_[numbering.toGlobal(l)] != label(g)) continue;
            for (const labelList* ids : {&movingPatchIDs, &staticPatchIDs})
            {
                for (const label patchi : *ids)
                {
                    const polyPatch& pp = mesh.boundaryMesh()[patchi];
                    if (pp.meshPointMap().found(localPoints_[l]) && !names.found(pp.name()))
                    {
                        names.append(pp.name());
                    }
                }
            }
        }
        wordList merged;
        string text;
        for (const wordList& l : dcpRBFCompat::allGather<word>(names))
        {
            for (const word& w : l)
            {
                if (merged.found(w)) continue;
                merged.append(w);
                text += (text.empty() ? "" : " ") + w;
            }
        }
        return text;
    };
    const string a(patchesOf(i));
    const string b(patchesOf(j));
    FatalErrorInFunction
        << "Boundary points " << label(i) << " and " << label(j) << " of"
        << " movingPatches and staticPatches coincide to round-off at "
        << projection_.pointFromCore(points_.row(i).data())
        << " without being the same point: one is on " << a.c_str()
        << ", the other on " << b.c_str() << " (two patches at the same place, the"
        << " two sides of an interface or of a baffle, say). List only one"
        << " of the patches, or make the points one (stitchMesh, or"
        << " mergeOrSplitBaffles for a baffle)" << exit(FatalError);
}


void Foam::dcpRBFBoundaryPoints::selectLocal
(
    const pointField& points0,
    DynamicList<bool>& localMoving
)
{
    DynamicList<label> labels;
    forAll(kind_, pointi)
    {
        const pointKind k = kind_[pointi];
        if
        (
            (k == staticPoint || k == movingPoint)
         && projection_.isControlCandidate(points0[pointi])
        )
        {
            labels.append(pointi);
            localMoving.append(kind_[pointi] == movingPoint);
        }
    }
    localPoints_.transfer(labels);
}


void Foam::dcpRBFBoundaryPoints::numberCanonically
(
    const DynamicList<FixedList<double, 3>>& coords,
    const DynamicList<bool>& isMoving
)
{
    std::vector<label> order(coords.size());
    std::iota(order.begin(), order.end(), 0);
    const auto less = [&](label a, label b)
    {
        return std::lexicographical_compare
        (
            coords[a].begin(), coords[a].end(),
            coords[b].begin(), coords[b].end()
        );
    };
    std::stable_sort(order.begin(), order.end(), less);

    concatToGlobal_.setSize(coords.size());
    DynamicList<label> unique;
    for (const label k : order)
    {
        if (unique.empty() || coords[unique.last()] != coords[k])
        {
            unique.append(k);
        }
        concatToGlobal_[k] = unique.size() - 1;
    }

    points_.resize(unique.size(), 3);
    moving_.setSize(unique.size(), false);
    forAll(unique, g)
    {
        for (int d = 0; d < 3; ++d) points_(g, d) = coords[unique[g]][d];
    }
    forAll(concatToGlobal_, k)
    {
        moving_[concatToGlobal_[k]] = moving_[concatToGlobal_[k]] || isMoving[k];
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFBoundaryPoints::dcpRBFBoundaryPoints
(
    const polyMesh& mesh,
    const dcpRBFPlaneProjection& projection,
    const labelList& movingPatchIDs,
    const labelList& staticPatchIDs,
    const pointField& points0,
    const dcpRBFRegion* region
)
:
    projection_(projection)
{
    // (not "region ? *region : wholeMesh(mesh)", which copies the region)
    if (region)
    {
        markPoints(mesh, movingPatchIDs, staticPatchIDs, *region);
    }
    else
    {
        markPoints(mesh, movingPatchIDs, staticPatchIDs, dcpRBFRegion::wholeMesh(mesh));
    }
    DynamicList<bool> localMoving;
    selectLocal(points0, localMoving);

    // All processors' candidates, concatenated in processor order
    const List<List<point>> allPoints
    (
        dcpRBFCompat::allGather<point>(pointField(points0, localPoints_))
    );
    const List<List<bool>> allMoving(dcpRBFCompat::allGather<bool>(localMoving));

    DynamicList<FixedList<double, 3>> coords;
    DynamicList<bool> isMoving;
    forAll(allPoints, proci)
    {
        forAll(allPoints[proci], i)
        {
            FixedList<double, 3> c;
            projection_.toCore(allPoints[proci][i], c.data());
            coords.append(c);
            isMoving.append(allMoving[proci][i]);
        }
    }

    numberCanonically(coords, isMoving);
    checkDistinct(mesh, movingPatchIDs, staticPatchIDs);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

dcprbf::Points Foam::dcpRBFBoundaryPoints::movingPoints() const
{
    dcprbf::Points p(std::count(moving_.begin(), moving_.end(), true), 3);
    Eigen::Index n = 0;
    forAll(moving_, i)
    {
        if (moving_[i]) p.row(n++) = points_.row(i);
    }
    return p;
}


Foam::globalIndex Foam::dcpRBFBoundaryPoints::holders() const
{
    return globalIndex(localPoints_.size());
}


Foam::labelList Foam::dcpRBFBoundaryPoints::holderOf() const
{
    // (concatToGlobal_ is in holders()'s numbering: the first k wins, then
    // this processor's own)
    labelList holder(size(), -1);
    forAll(concatToGlobal_, k)
    {
        if (holder[concatToGlobal_[k]] < 0) holder[concatToGlobal_[k]] = k;
    }
    const globalIndex numbering(holders());
    forAll(localPoints_, i)
    {
        const label k = numbering.toGlobal(i);
        holder[concatToGlobal_[k]] = k;
    }
    return holder;
}


std::vector<bool> Foam::dcpRBFBoundaryPoints::gatherFlags
(
    const boolList& flag
) const
{
    labelList local(localPoints_.size(), 0);
    forAll(localPoints_, i)
    {
        local[i] = flag[localPoints_[i]];
    }
    const List<List<label>> all(dcpRBFCompat::allGather<label>(local));
    std::vector<bool> global(size(), false);
    label k = 0;
    for (const List<label>& procFlags : all)
    {
        for (const label f : procFlags)
        {
            global[concatToGlobal_[k++]] = f;
        }
    }
    return global;
}


dcprbf::Values Foam::dcpRBFBoundaryPoints::gather
(
    const pointField& prescribed
) const
{
    vectorField local(localPoints_.size(), Zero);
    forAll(localPoints_, i)
    {
        if (kind_[localPoints_[i]] == movingPoint)
        {
            local[i] = prescribed[localPoints_[i]];
        }
    }
    const List<List<vector>> all(dcpRBFCompat::allGather<vector>(local));

    dcprbf::Values values(dcprbf::Values::Zero(size(), 3));
    label k = 0;
    for (const List<vector>& procValues : all)
    {
        for (const vector& v : procValues)
        {
            projection_.toCore(v, values.row(concatToGlobal_[k++]).data());
        }
    }
    return values;
}


// ************************************************************************* //
