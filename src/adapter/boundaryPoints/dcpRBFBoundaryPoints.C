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

#include <algorithm>
#include <numeric>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
Foam::List<Foam::List<Type>> Foam::dcpRBFBoundaryPoints::allGather
(
    const List<Type>& local
)
{
    List<List<Type>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = local;
    dcpRBFCompat::allGatherList(all);
    return all;
}


void Foam::dcpRBFBoundaryPoints::markPoints
(
    const polyMesh& mesh,
    const labelList& movingPatchIDs,
    const labelList& staticPatchIDs
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
    kind_.setSize(kind.size());
    forAll(kind, pointi)
    {
        kind_[pointi] = pointKind(kind[pointi]);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFBoundaryPoints::dcpRBFBoundaryPoints
(
    const polyMesh& mesh,
    const dcpRBFPlaneProjection& projection,
    const labelList& movingPatchIDs,
    const labelList& staticPatchIDs,
    const pointField& points0
)
:
    projection_(projection)
{
    markPoints(mesh, movingPatchIDs, staticPatchIDs);
    DynamicList<label> labels;
    DynamicList<bool> localMoving;
    forAll(kind_, pointi)
    {
        if (kind_[pointi] != interiorPoint && projection_.isControlCandidate(points0[pointi]))
        {
            labels.append(pointi);
            localMoving.append(kind_[pointi] == movingPoint);
        }
    }
    localPoints_.transfer(labels);

    // All processors' candidates, concatenated in processor order
    const List<List<point>> allPoints
    (
        allGather<point>(pointField(points0, localPoints_))
    );
    const List<List<bool>> allMoving(allGather<bool>(localMoving));

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

    // Canonical order: lexicographic in core coordinates, duplicates merged
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
    const List<List<vector>> all(allGather<vector>(local));

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
