/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFSlipCorrection.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "PointTree.hpp"

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::dcpRBFSlipCorrection::slidingPatches
(
    const polyMesh& mesh,
    const labelList& movingPatchIDs,
    const labelList& staticPatchIDs
)
{
    // (the same list on every processor: processor patches are coupled)
    DynamicList<label> ids;
    forAll(mesh.boundaryMesh(), patchi)
    {
        const polyPatch& pp = mesh.boundaryMesh()[patchi];
        if
        (
            !movingPatchIDs.found(patchi)
         && !staticPatchIDs.found(patchi)
         && !isA<emptyPolyPatch>(pp)
         && !isA<wedgePolyPatch>(pp)
         && !pp.coupled()
        )
        {
            ids.append(patchi);
        }
    }
    return labelList(std::move(ids));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFSlipCorrection::dcpRBFSlipCorrection
(
    const polyMesh& mesh,
    const dcpRBFPlaneProjection& projection,
    const dcpRBFBoundaryPoints& boundary,
    const labelList& movingPatchIDs,
    const labelList& staticPatchIDs,
    const dcprbf::Points& evalPoints,
    const pointField& points0,
    const scalar maxRadius
)
:
    boundary_(boundary)
{
    const labelList ids(slidingPatches(mesh, movingPatchIDs, staticPatchIDs));
    if (ids.empty())
    {
        return;
    }
    // the sliding points as the "moving" points of a second set
    sliding_.reset
    (
        new dcpRBFBoundaryPoints(mesh, projection, ids, labelList(), points0)
    );
    if (sliding_->size() == 0)
    {
        sliding_.clear();
        return;
    }
    // corrected: the points on no patch of either kind
    boolList corrected(mesh.nPoints());
    forAll(corrected, pointi)
    {
        corrected[pointi] =
            boundary.kind(pointi) == dcpRBFBoundaryPoints::interiorPoint
         && sliding_->kind(pointi) == dcpRBFBoundaryPoints::interiorPoint;
    }
    // each sliding point's blend stays clear of the moving patches (they
    // are exact): within half its distance to the nearest moving point
    const dcprbf::Points& x = sliding_->points();
    scalarField radius(x.rows(), maxRadius);
    const dcprbf::Points moving(boundary.movingPoints());
    if (moving.rows())
    {
        const dcprbf::PointTree tree(moving);
        for (Eigen::Index i = 0; i < x.rows(); ++i)
        {
            double d2 = 0;
            tree.nearest(x.row(i).data(), d2);
            radius[i] = min(maxRadius, 0.5*std::sqrt(d2));
        }
    }
    blend_.reset
    (
        new dcpRBFBoundaryCorrection
        (
            evalPoints, x, corrected, maxRadius, radius
        )
    );
    before_.setSize(sliding_->localPoints().size(), Zero);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFSlipCorrection::keep(const vectorField& displacement)
{
    if (!active())
    {
        return;
    }
    before_ = vectorField(displacement, sliding_->localPoints());
}


Foam::scalar Foam::dcpRBFSlipCorrection::apply
(
    const dcpRBFPlaneProjection& projection,
    vectorField& displacement
) const
{
    if (!active())
    {
        return 0;
    }
    // the change at the sliding points (none where a moving or static
    // patch's condition sets the point)
    const labelList& local = sliding_->localPoints();
    vectorField change(local.size(), Zero);
    forAll(local, i)
    {
        if (boundary_.kind(local[i]) == dcpRBFBoundaryPoints::interiorPoint)
        {
            change[i] = displacement[local[i]] - before_[i];
        }
    }
    return blend_->apply(sliding_->gatherLocal(change), projection, displacement);
}


// ************************************************************************* //
