/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFSlidingWalls.H"
#include "basicSymmetryPointPatchField.H"
#include "syncTools.H"
#include "primitivePatch.H"
#include "unitConversion.H"

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::dcpRBFSlidingWalls::slidingPatches
(
    const pointVectorField& displacement,
    const labelList& movingPatchIDs,
    const labelList& staticPatchIDs
)
{
    // (the same list on every processor: processor patches are coupled,
    // not of these)
    const pointVectorField::Boundary& bf = displacement.boundaryField();
    DynamicList<label> ids;
    forAll(bf, patchi)
    {
        if
        (
            !movingPatchIDs.found(patchi)
         && !staticPatchIDs.found(patchi)
         && isA<basicSymmetryPointPatchField<vector>>(bf[patchi])
        )
        {
            ids.append(patchi);
        }
    }
    return labelList(std::move(ids));
}


Foam::List<Foam::Map<Foam::vector>> Foam::dcpRBFSlidingWalls::pointNormals
(
    const polyMesh& mesh,
    const labelList& ids,
    const pointField& points0
)
{
    // (kept per patch for its points only: one field of every point at
    // a time)
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    List<Map<vector>> normals(ids.size());
    forAll(ids, a)
    {
        const polyPatch& pp = patches[ids[a]];
        const primitivePatch p0
        (
            SubList<face>(mesh.faces(), pp.size(), pp.start()), points0
        );
        vectorField n(mesh.nPoints(), Zero);
        UIndirectList<vector>(n, p0.meshPoints()) = p0.pointNormals();
        syncTools::syncPointList(mesh, n, plusEqOp<vector>(), vector::zero);
        forAll(n, pointi)
        {
            if (magSqr(n[pointi]) > 0) normals[a].insert(pointi, n[pointi]);
        }
    }
    return normals;
}


Foam::List<Foam::labelList> Foam::dcpRBFSlidingWalls::group
(
    const polyMesh& mesh,
    const labelList& ids,
    const pointField& points0
)
{
    const List<Map<vector>> normals(pointNormals(mesh, ids, points0));

    // per sliding patch its wall (the first patch of the wall): patches
    // sharing a point whose normals agree there, on every processor
    const scalar cosMax = std::cos(degToRad(sameWallAngle));
    labelList wallOf(ids);
    forAll(ids, a)
    {
        for (label b = a + 1; b < ids.size(); ++b)
        {
            bool shared = false, parallel = true;
            forAllConstIters(normals[a], iter)
            {
                const auto other = normals[b].cfind(iter.key());
                if (other.found())
                {
                    const vector& na = iter.val();
                    const vector& nb = *other;
                    shared = true;
                    parallel = parallel && (na & nb) > cosMax*mag(na)*mag(nb);
                }
            }
            if
            (
                returnReduce(shared, orOp<bool>())
             && returnReduce(parallel, andOp<bool>())
            )
            {
                // b's wall joins a's
                const label from = wallOf[b], to = wallOf[a];
                for (label& w : wallOf)
                {
                    if (w == from) w = to;
                }
            }
        }
    }
    List<labelList> result;
    forAll(ids, a)
    {
        if (wallOf[a] == ids[a])
        {
            labelList wall;
            forAll(ids, b)
            {
                if (wallOf[b] == ids[a]) wall.append(ids[b]);
            }
            result.append(wall);
        }
    }
    return result;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFSlidingWalls::dcpRBFSlidingWalls
(
    const polyMesh& mesh,
    const pointVectorField& displacement,
    const labelList& movingPatchIDs,
    const labelList& staticPatchIDs,
    const pointField& points0
)
:
    walls_
    (
        group
        (
            mesh, slidingPatches(displacement, movingPatchIDs, staticPatchIDs),
            points0
        )
    ),
    seams_(walls_.size())
{
    forAll(walls_, w)
    {
        if (walls_[w].size() < 2)
        {
            continue;
        }
        // the points on two or more of the wall's patches (synchronised)
        labelField onPatches(mesh.nPoints(), 0);
        for (const label patchi : walls_[w])
        {
            labelField on(mesh.nPoints(), 0);
            UIndirectList<label>(on, mesh.boundaryMesh()[patchi].meshPoints()) = 1;
            syncTools::syncPointList(mesh, on, maxEqOp<label>(), label(0));
            onPatches += on;
        }
        forAll(onPatches, pointi)
        {
            if (onPatches[pointi] > 1) seams_[w].insert(pointi);
        }
    }
}


// ************************************************************************* //
