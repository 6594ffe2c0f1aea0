/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFPrescribedDisplacement.H"
#include "valuePointPatchField.H"
#include "pointConstraints.H"
#include "syncTools.H"
#include "emptyPolyPatch.H"
#include "emptyPointPatch.H"
#include "pointMesh.H"

#include <cstring>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFPrescribedDisplacement::dcpRBFPrescribedDisplacement
(
    const dcpRBFContext& context
)
:
    mesh_(context.mesh()),
    settings_(context.settings()),
    projection_(context.projection()),
    boundaryPoints_(context.boundaryPoints()),
    region_(context.region()),
    stepMesh_(context.stepMesh()),
    slipPatches_(stepMesh_.field(), context.points0()),
    slipCorrection_
    (
        mesh_, stepMesh_.field(), projection_, boundaryPoints_,
        settings_.movingPatchIDs(), settings_.staticPatchIDs(),
        context.evalPoints(), context.points0(), settings_.kernel().radius()
    )
{
    // The prescribed points, and those finish() can change (std::vector:
    // GCC's alloc-size-larger-than on a boolList of nPoints)
    std::vector<char> mark(std::size_t(mesh_.nPoints()), false);
    DynamicList<label> prescribed;
    for (label pointi = 0; pointi < mesh_.nPoints(); ++pointi)
    {
        if (boundaryPoints_.kind(pointi) != dcpRBFBoundaryPoints::interiorPoint)
        {
            mark[pointi] = true;
            prescribed.append(pointi);
        }
    }
    boundaryMeshPoints_.transfer(prescribed);
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (!isA<emptyPolyPatch>(pp))
        {
            for (const label pointi : pp.meshPoints())
            {
                mark[pointi] = true;
            }
        }
    }
    DynamicList<label> finished;
    for (label pointi = 0; pointi < mesh_.nPoints(); ++pointi)
    {
        if (mark[pointi]) finished.append(pointi);
    }
    finishedPoints_.transfer(finished);
    collectCoupledConstraints();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFPrescribedDisplacement::collectCoupledConstraints()
{
    if (!Pstream::parRun())
    {
        return;
    }
    // every point of every constraint patch (pointConstraints: the patches'
    // edge points only), combined over the processors sharing it; not the
    // slip and symmetry conditions' (dcpRBFSlipPatches: their reference
    // normals, the same on every processor)
    const pointBoundaryMesh& pbm = pointMesh::New(mesh_).boundary();
    List<pointConstraint> constraints(mesh_.nPoints());
    for (const pointPatch& pp : pbm)
    {
        if (pp.coupled() || isA<emptyPointPatch>(pp) || slipPatches_.handles(pp.index()))
        {
            continue;
        }
        const labelList& meshPoints = pp.meshPoints();
        forAll(meshPoints, i)
        {
            pp.applyConstraint(i, constraints[meshPoints[i]]);
        }
    }
    syncTools::syncPointList
    (
        mesh_, constraints, combineConstraintsEqOp(), pointConstraint()
    );
    DynamicList<label> points;
    DynamicList<pointConstraint> kept;
    for (const label pointi : mesh_.globalData().coupledPatch().meshPoints())
    {
        if (constraints[pointi].first() > 0)
        {
            points.append(pointi);
            kept.append(constraints[pointi]);
        }
    }
    coupledConstrainedPoints_.transfer(points);
    coupledConstraints_.transfer(kept);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::dcpRBFPrescribedDisplacement::selfMovedNames() const
{
    string names;
    for (const label patchi : selfMoved_)
    {
        names += (names.empty() ? "" : " ") + mesh_.boundaryMesh()[patchi].name();
    }
    return names;
}


void Foam::dcpRBFPrescribedDisplacement::checkMovingPatch
(
    const dictionary& dict,
    const polyPatch& pp
) const
{
    bool crosses = false;
    for (const label pointi : pp.meshPoints())
    {
        crosses = crosses || !region_.point(pointi) || region_.border(pointi);
    }
    if (returnReduce(crosses, orOp<bool>()))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword movingPatches: patch " << pp.name() << " crosses"
            << " the border of the region dcpRBF moves ("
            << region_.source().c_str() << "): its points there are"
            << " shared with cells outside the region, which dcpRBF"
            << " neither moves nor checks, or lie on the region's side"
            << " of a sliding interface, which stays on it. Make the"
            << " cellZone hold every cell of the moving patch's faces"
            << " and their neighbours, and keep the patch off the"
            << " interface"
            << exit(FatalIOError);
    }
    const pointPatchVectorField& condition =
        stepMesh_.field().boundaryField()[pp.index()];
    if (!condition.fixesValue())
    {
        FatalIOErrorInFunction(dict)
            << "Keyword movingPatches: patch " << pp.name() << " has"
            << " the pointDisplacement condition " << condition.type()
            << ", which does not prescribe the displacement: nothing"
            << " would move. Use a fixed-value condition"
            << " (fixedValue, angularOscillatingDisplacement,"
            << " solidBodyMotionDisplacement,"
            << " sixDoFRigidBodyDisplacement, surfaceDisplacement,"
            << " codedFixedValue, ...); a patch whose points should"
            << " slide (slip, fixedNormalSlip) goes in neither list,"
            << " one that stays put under staticPatches"
            << exit(FatalIOError);
    }
}


void Foam::dcpRBFPrescribedDisplacement::checkPatches(const dictionary& dict)
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const pointVectorField::Boundary& conditions =
        stepMesh_.field().boundaryField();
    wordList unlisted;
    // (touches() is collective: not over the processor patches, whose
    // number differs between processors)
    for (label patchi = 0; patchi < patches.nNonProcessor(); ++patchi)
    {
        const polyPatch& pp = patches[patchi];
        if (!region_.touches(patchi))
        {
            // outside the region: its points stay where they are
            if (settings_.movingPatchIDs().found(patchi))
            {
                FatalIOErrorInFunction(dict)
                    << "Keyword movingPatches: patch " << pp.name() << " is"
                    << " outside the region dcpRBF moves ("
                    << region_.source().c_str() << "): its points would not"
                    << " move. List the patches of the region's cells"
                    << exit(FatalIOError);
            }
            continue;
        }
        if (settings_.movingPatchIDs().found(patchi))
        {
            checkMovingPatch(dict, pp);
        }
        else if
        (
            !settings_.staticPatchIDs().found(patchi)
         && !polyPatch::constraintType(pp.type())
        )
        {
            if (conditions[patchi].fixesValue())
            {
                selfMoved_.append(patchi);
            }
            else
            {
                unlisted.append(pp.name());
            }
        }
    }
    if (selfMoved_.size())
    {
        WarningInFunction
            << "Patches in neither movingPatches nor staticPatches whose"
            << " pointDisplacement condition fixes their points' values: "
            << selfMovedNames().c_str() << nl
            << "    Their points go where their conditions put them, but"
            << " the interpolation does not know of them: if they move, only"
            << " the cells touching them follow (they fold for a motion"
            << " larger than those cells; the check covers them). List a"
            << " patch that moves under movingPatches, one that stays put"
            << " under staticPatches." << endl;
    }
    // (inferred lists: the inference's log line has named them, sliding)
    if (unlisted.size() && !settings_.patchesInferred())
    {
        WarningInFunction
            << "Patches in neither movingPatches nor staticPatches: "
            << unlisted << nl
            << "    Their points move with the interpolated displacement,"
            << " then their own pointDisplacement condition applies (a slip"
            << " wall's removes the normal part, which is spread back into the"
            << " volume next to it; constraint patches such as symmetryPlane"
            << " are not listed)."
            << endl;
    }
}


void Foam::dcpRBFPrescribedDisplacement::read()
{
    // The only evaluation of the conditions this step: constrain() and
    // finish() insert the values without
    // re-evaluating. The step's mesh is new from here
    pointVectorField::Boundary& bf = stepMesh_.change().boundaryFieldRef();
    bf.updateCoeffs();

    // Only moving points hold a value: zero elsewhere once, then only the
    // moving points cleared (a pass over every point costs as much as the
    // rest of this function)
    if (prescribed_.size() != mesh_.nPoints())
    {
        prescribed_.setSize(mesh_.nPoints());
        prescribed_ = Zero;
        movingMeshPoints_.clear();
        forAll(prescribed_, pointi)
        {
            if (boundaryPoints_.kind(pointi) == dcpRBFBoundaryPoints::movingPoint)
            {
                movingMeshPoints_.append(pointi);
            }
        }
    }
    for (const label pointi : movingMeshPoints_)
    {
        prescribed_[pointi] = Zero;
    }
    for (const label patchi : settings_.movingPatchIDs())
    {
        // fixesValue() was checked at construction (checkPatches())
        bf[patchi].setInInternalField
        (
            prescribed_,
            refCast<const valuePointPatchField<vector>>(bf[patchi])
        );
    }
    // Points of a moving patch held by a processor without its faces
    syncTools::syncPointList
    (
        mesh_, prescribed_, maxMagSqrEqOp<vector>(), vector::zero
    );
}


void Foam::dcpRBFPrescribedDisplacement::constrain()
{
    pointVectorField& pointDisplacement = stepMesh_.change();
    pointVectorField::Boundary& bf = pointDisplacement.boundaryFieldRef();
    forAll(bf, patchi)
    {
        // each sliding patch's change kept for dcpRBFSlipCorrection
        slipCorrection_.keep(patchi, pointDisplacement.primitiveField());
        if (slipPatches_.handles(patchi))
        {
            slipPatches_.evaluate(pointDisplacement, patchi);
        }
        else if (!bf[patchi].fixesValue())
        {
            bf[patchi].evaluate();
        }
        else if (selfMoved_.found(patchi))
        {
            // a patch in neither list whose condition fixes its values
            // (evaluated in read()): in place before the mesh is
            // measured, as the final constraints put it
            bf[patchi].setInInternalField
            (
                pointDisplacement.primitiveFieldRef(),
                refCast<const valuePointPatchField<vector>>(bf[patchi])
            );
        }
        slipCorrection_.record(patchi, pointDisplacement.primitiveField());
    }
    const pointConstraints& pcs = pointConstraints::New(pointDisplacement.mesh());
    pointConstraints::syncUntransformedData
    (
        mesh_, pointDisplacement.primitiveFieldRef(), maxMagSqrEqOp<vector>()
    );
    // (the synchronisation took the larger value: a processor's that does
    // not hold the constraint patch's faces)
    vectorField& disp = pointDisplacement.primitiveFieldRef();
    forAll(coupledConstrainedPoints_, i)
    {
        vector& d = disp[coupledConstrainedPoints_[i]];
        d = coupledConstraints_[i].constrainDisplacement(d);
    }
    pcs.constrainCorners(pointDisplacement);
}


void Foam::dcpRBFPrescribedDisplacement::constrainInterpolated()
{
    vectorField& disp = stepMesh_.change().primitiveFieldRef();
    constrain();
    if (slipCorrection_.apply(projection_, disp) > 0 && slipCorrection_.size() > 1)
    {
        // the walls' blends moved points of the other walls: their
        // conditions once more
        constrain();
    }
}


void Foam::dcpRBFPrescribedDisplacement::insert(vectorField& disp) const
{
    for (const label pointi : boundaryMeshPoints_)
    {
        disp[pointi] = prescribed_[pointi];
    }
}


void Foam::dcpRBFPrescribedDisplacement::finish()
{
    // The fixed-value conditions' values inserted (not re-evaluated: this
    // completes the step's one evaluation), the constraints applied as
    // pointConstraints::constrainDisplacement does, but for its 2D
    // correction of the displacement: curPoints() corrects the points, so
    // the displacement stays the one the quality was measured for. (In 2D
    // the interior front and back twins have the same displacement by
    // construction: one value per distinct point, the correction by the
    // same nearest boundary point; the boundary points get their prescribed
    // values below.) Then the listed patches' rule, the same on every
    // processor: moving points where prescribed (also where a static
    // patch's condition says otherwise), static points in place
    const label version = stepMesh_.version();
    pointVectorField& pointDisplacement = stepMesh_.change();
    vectorField& disp = pointDisplacement.primitiveFieldRef();
    // the only points this can change
    finishedBefore_.setSize(finishedPoints_.size());
    forAll(finishedPoints_, i)
    {
        finishedBefore_[i] = disp[finishedPoints_[i]];
    }
    pointDisplacement.setUpToDate();
    pointDisplacement.storeOldTimes();
    pointVectorField::Boundary& bf = pointDisplacement.boundaryFieldRef();
    forAll(bf, patchi)
    {
        if (bf[patchi].fixesValue())
        {
            bf[patchi].evaluate();
        }
    }
    constrain();
    insert(disp);
    bool unchanged = true;
    for (label i = 0; unchanged && i < finishedPoints_.size(); ++i)
    {
        // bitwise, as the measured points were made
        unchanged =
            std::memcmp(&finishedBefore_[i], &disp[finishedPoints_[i]], sizeof(vector)) == 0;
    }
    if (unchanged)
    {
        stepMesh_.unchanged(version);
    }
}


// ************************************************************************* //
