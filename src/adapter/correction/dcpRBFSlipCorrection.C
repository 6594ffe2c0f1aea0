/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFSlipCorrection.H"
#include "syncTools.H"
#include "PointTree.hpp"

#include <cmath>
#include <vector>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFSlipCorrection::dcpRBFSlipCorrection
(
    const polyMesh& mesh,
    const pointVectorField& displacement,
    const dcpRBFPlaneProjection& projection,
    const dcpRBFBoundaryPoints& boundary,
    const labelList& movingPatchIDs,
    const labelList& staticPatchIDs,
    const dcprbf::Points& evalPoints,
    const pointField& points0,
    const scalar maxRadius
)
:
    mesh_(mesh),
    boundary_(boundary)
{
    const dcpRBFSlidingWalls walls
    (
        mesh, displacement, movingPatchIDs, staticPatchIDs, points0
    );
    wallOf_.setSize(mesh.boundaryMesh().size(), -1);
    placeOf_.setSize(mesh.boundaryMesh().size(), -1);
    const dcprbf::Points moving(boundary.movingPoints());
    autoPtr<dcprbf::PointTree> movingTree;
    if (moving.rows())
    {
        movingTree.reset(new dcprbf::PointTree(moving));
    }
    forAll(walls, wi)
    {
        // the wall's points as the "moving" points of a set of their own
        // (the same patches on every processor: the same sets)
        autoPtr<dcpRBFBoundaryPoints> points
        (
            new dcpRBFBoundaryPoints
            (
                mesh, projection, walls.patches(wi), labelList(), points0
            )
        );
        if (points->size() == 0)
        {
            continue;
        }
        wall* w = new wall;
        w->blend.reset
        (
            new dcpRBFBoundaryCorrection
            (
                evalPoints, *points, corrected(*points), maxRadius,
                blendRadii(points->points(), movingTree.get(), maxRadius)
            )
        );
        w->points = std::move(points);
        index(*w, walls, wi);
        walls_.append(w);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::boolList Foam::dcpRBFSlipCorrection::corrected
(
    const dcpRBFBoundaryPoints& wallPoints
) const
{
    // the points on no moving or static patch and not on this wall
    boolList corrected(mesh_.nPoints());
    forAll(corrected, pointi)
    {
        const bool onThis =
            wallPoints.kind(pointi) != dcpRBFBoundaryPoints::interiorPoint;
        corrected[pointi] =
            boundary_.kind(pointi) == dcpRBFBoundaryPoints::interiorPoint
         && !onThis;
    }
    return corrected;
}


Foam::scalarField Foam::dcpRBFSlipCorrection::blendRadii
(
    const dcprbf::Points& x,
    const dcprbf::PointTree* movingTree,
    const scalar maxRadius
)
{
    // each point's blend stays clear of the moving patches (they are
    // exact): within half its distance to the nearest moving point
    scalarField radius(x.rows(), maxRadius);
    if (movingTree)
    {
        for (Eigen::Index i = 0; i < x.rows(); ++i)
        {
            double d2 = 0;
            movingTree->nearest(x.row(i).data(), d2);
            radius[i] = min(maxRadius, 0.5*std::sqrt(d2));
        }
    }
    return radius;
}


void Foam::dcpRBFSlipCorrection::index
(
    wall& w,
    const dcpRBFSlidingWalls& walls,
    const label wi
)
{
    // each patch's points among the wall's, the seams; the patches' wall
    // and place (the wall is the next of walls_)
    const labelList& patchIDs = walls.patches(wi);
    const labelList& localPoints = w.points->localPoints();
    w.patches = patchIDs;
    w.members.setSize(patchIDs.size());
    forAll(patchIDs, k)
    {
        const Map<label>& onPatch = mesh_.boundaryMesh()[patchIDs[k]].meshPointMap();
        DynamicList<label> members;
        forAll(localPoints, i)
        {
            if (onPatch.found(localPoints[i])) members.append(i);
        }
        w.members[k].transfer(members);
        wallOf_[patchIDs[k]] = walls_.size();
        placeOf_[patchIDs[k]] = k;
    }
    DynamicList<label> seams;
    forAll(localPoints, i)
    {
        if (walls.onSeam(wi, localPoints[i])) seams.append(i);
    }
    w.seams.transfer(seams);
    w.seamBefore.setSize(w.seams.size(), Zero);
    w.before.setSize(localPoints.size(), Zero);
    w.change.setSize(localPoints.size(), Zero);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFSlipCorrection::keep
(
    const label patchi,
    const vectorField& displacement
)
{
    if (wallOf_.size() && wallOf_[patchi] >= 0)
    {
        // (into the storage kept: constrain() runs several times a step;
        // the wall's first patch starts its change anew)
        wall& w = walls_[wallOf_[patchi]];
        const labelList& local = w.points->localPoints();
        if (placeOf_[patchi] == 0)
        {
            w.change = Zero;
            forAll(w.seams, k)
            {
                w.seamBefore[k] = displacement[local[w.seams[k]]];
            }
        }
        for (const label i : w.members[placeOf_[patchi]])
        {
            w.before[i] = displacement[local[i]];
        }
    }
}


void Foam::dcpRBFSlipCorrection::record
(
    const label patchi,
    const vectorField& displacement
)
{
    if (wallOf_.size() && wallOf_[patchi] >= 0)
    {
        // added up over the wall's patches (their shared points)
        wall& w = walls_[wallOf_[patchi]];
        const labelList& local = w.points->localPoints();
        for (const label i : w.members[placeOf_[patchi]])
        {
            if (boundary_.kind(local[i]) == dcpRBFBoundaryPoints::interiorPoint)
            {
                w.change[i] += displacement[local[i]] - w.before[i];
            }
        }
    }
}


Foam::scalar Foam::dcpRBFSlipCorrection::apply
(
    const dcpRBFPlaneProjection& projection,
    vectorField& displacement
) const
{
    // every wall's change first (the blends then move points of the other
    // walls): per point this processor holds (the blend fetches the others
    // it needs)
    List<dcprbf::Values> changes(walls_.size());
    std::vector<char> blended(std::size_t(walls_.size()), 0);
    forAll(walls_, w)
    {
        const labelList& local = walls_[w].points->localPoints();
        // the seam points' change: the constrained displacement minus the
        // one before the wall's conditions
        vectorField ownChange(walls_[w].change);
        forAll(walls_[w].seams, k)
        {
            const label i = walls_[w].seams[k];
            if (boundary_.kind(local[i]) == dcpRBFBoundaryPoints::interiorPoint)
            {
                ownChange[i] = displacement[local[i]] - walls_[w].seamBefore[k];
            }
        }
        // a wall whose condition changed nothing (a symmetry plane the
        // motion runs along): no blend (one reduction)
        if (returnReduce(max(magSqr(ownChange)), maxOp<scalar>()) <= 0)
        {
            continue;
        }
        if (Pstream::parRun())
        {
            // a processor holding a wall point without the wall's faces
            // there recorded no change: the change of the one with them
            // (the largest, as constrain()'s synchronisation takes), the
            // same on every processor
            pointField change(mesh_.nPoints(), Zero);
            UIndirectList<vector>(change, local) = ownChange;
            syncTools::syncPointList
            (
                mesh_, change, maxMagSqrEqOp<vector>(), vector::zero
            );
            changes[w] = projection.toCore(vectorField(change, local));
        }
        else
        {
            changes[w] = projection.toCore(ownChange);
        }
        blended[w] = true;
    }
    scalar radius = 0;
    forAll(walls_, w)
    {
        if (blended[w])
        {
            radius = max(radius, walls_[w].blend->apply(changes[w], projection, displacement));
        }
    }
    return radius;
}


// ************************************************************************* //
