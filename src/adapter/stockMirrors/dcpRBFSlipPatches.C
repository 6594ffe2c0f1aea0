/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFSlipPatches.H"
#include "slipPointPatchField.H"
#include "fixedNormalSlipPointPatchField.H"
#include "symmetryPointPatchField.H"
#include "facePointPatch.H"
#include "primitivePatch.H"
#include "PatchTools.H"
#include "transformField.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFSlipPatches::dcpRBFSlipPatches
(
    const pointVectorField& displacement,
    const pointField& points0
)
:
    slip_(displacement.boundaryField().size(), false),
    normals0_(displacement.boundaryField().size()),
    danglingPoints_(displacement.boundaryField().size()),
    danglingNormals0_(displacement.boundaryField().size())
{
    const polyMesh& mesh = displacement.mesh().mesh();
    forAll(displacement.boundaryField(), patchi)
    {
        const pointPatchVectorField& pf = displacement.boundaryField()[patchi];
        // slip and symmetry; not fixedNormalSlip (derived from slip: its
        // own normal), nor symmetryPlane (not derived from symmetry)
        const bool slip =
            (
                isA<slipPointPatchField<vector>>(pf)
             && !isA<fixedNormalSlipPointPatchField<vector>>(pf)
            )
         || isA<symmetryPointPatchField<vector>>(pf);
        if (!slip || !isA<facePointPatch>(pf.patch()))
        {
            continue;
        }
        const polyPatch& pp = refCast<const facePointPatch>(pf.patch()).patch();
        // the patch's faces on the reference points: the same local point
        // order as the patch (first appearance in its faces)
        const primitivePatch pp0
        (
            SubList<face>(mesh.faces(), pp.size(), pp.start()),
            points0
        );
        if (pp0.meshPoints() != pp.meshPoints())
        {
            FatalErrorInFunction
                << "Patch " << pp.name() << ": the reference patch's points"
                << " differ from the patch's" << abort(FatalError);
        }
        slip_[patchi] = true;
        // averaged over the faces of every processor holding the point (the
        // same normal on each; collective: every rank has the same
        // non-processor patches in the same order)
        normals0_[patchi] = PatchTools::pointNormals(mesh, pp0);

        // The points of the patch on other processors only: their normals
        // from those (a processor holding a patch point without the
        // patch's faces would keep the normal part, and the
        // synchronisation of the displacement takes the larger value)
        vectorField all(mesh.nPoints(), Zero);
        UIndirectList<vector>(all, pp.meshPoints()) = normals0_[patchi];
        syncTools::syncPointList(mesh, all, maxMagSqrEqOp<vector>(), vector::zero);
        const Map<label>& onPatch = pp.meshPointMap();
        DynamicList<label> dangling;
        forAll(all, pointi)
        {
            if (magSqr(all[pointi]) > 0 && !onPatch.found(pointi))
            {
                dangling.append(pointi);
            }
        }
        danglingPoints_[patchi].transfer(dangling);
        danglingNormals0_[patchi] = vectorField(all, danglingPoints_[patchi]);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFSlipPatches::evaluate
(
    pointVectorField& displacement,
    const label patchi
) const
{
    const pointPatchVectorField& pf = displacement.boundaryField()[patchi];
    const vectorField& nHat = normals0_[patchi];
    const vectorField v(pf.patchInternalField());
    const vectorField values((v + transform(I - 2.0*sqr(nHat), v))/2.0);
    pf.setInInternalField(displacement.primitiveFieldRef(), values);

    // the same at the patch's points whose faces are on other processors
    const labelList& dangling = danglingPoints_[patchi];
    const vectorField& nDangling = danglingNormals0_[patchi];
    vectorField& d = displacement.primitiveFieldRef();
    forAll(dangling, i)
    {
        const vector u(d[dangling[i]]);
        d[dangling[i]] = (u + transform(I - 2.0*sqr(nDangling[i]), u))/2.0;
    }
}


// ************************************************************************* //
