/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFMotionSolver, continued: the displacement of every point (the
    boundary conditions' one evaluation, the interpolation, the
    constraints).
\*---------------------------------------------------------------------------*/

#include "dcpRBFMotionSolver.H"
#include "valuePointPatchField.H"
#include "pointConstraints.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFMotionSolver::readPrescribed()
{
    // The only evaluation of the conditions this step: constrain() and the
    // final constraints (end of solve()) insert the values without
    // re-evaluating
    pointVectorField::Boundary& bf = pointDisplacement_.boundaryFieldRef();
    bf.updateCoeffs();

    // Only moving points hold a value: zero elsewhere once, then only the
    // moving points cleared (a pass over every point costs as much as the
    // rest of this function)
    if (prescribed_.size() != mesh().nPoints())
    {
        prescribed_.setSize(mesh().nPoints());
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
        // fixesValue() was checked at construction (checkPatches)
        bf[patchi].setInInternalField
        (
            prescribed_,
            refCast<const valuePointPatchField<vector>>(bf[patchi])
        );
    }
    // Points of a moving patch held by a processor without its faces
    syncTools::syncPointList
    (
        mesh(), prescribed_, maxMagSqrEqOp<vector>(), vector::zero
    );
}


void Foam::dcpRBFMotionSolver::constrain()
{
    pointVectorField::Boundary& bf = pointDisplacement_.boundaryFieldRef();
    forAll(bf, patchi)
    {
        // each sliding patch's change kept for dcpRBFSlipCorrection
        slipCorrection_.keep(patchi, pointDisplacement_.primitiveField());
        if (slipPatches_.handles(patchi))
        {
            slipPatches_.evaluate(pointDisplacement_, patchi);
        }
        else if (!bf[patchi].fixesValue())
        {
            bf[patchi].evaluate();
        }
        else if (selfMoved_.found(patchi))
        {
            // a patch in neither list whose condition fixes its values
            // (evaluated in readPrescribed()): in place before the mesh is
            // measured, as the final constraints put it
            bf[patchi].setInInternalField
            (
                pointDisplacement_.primitiveFieldRef(),
                refCast<const valuePointPatchField<vector>>(bf[patchi])
            );
        }
        slipCorrection_.record(patchi, pointDisplacement_.primitiveField());
    }
    const pointConstraints& pcs = pointConstraints::New(pointDisplacement_.mesh());
    pointConstraints::syncUntransformedData
    (
        mesh(), pointDisplacement_.primitiveFieldRef(), maxMagSqrEqOp<vector>()
    );
    pcs.constrainCorners(pointDisplacement_);
}


void Foam::dcpRBFMotionSolver::constrainInterpolated()
{
    vectorField& disp = pointDisplacement_.primitiveFieldRef();
    constrain();
    if (slipCorrection_.apply(projection_, disp) > 0 && slipCorrection_.size() > 1)
    {
        // the walls' blends moved points of the other walls: their
        // conditions once more
        constrain();
    }
}


bool Foam::dcpRBFMotionSolver::writesRowsToPoints() const
{
    return
        !rotation_.active()
     && projection_.axis(0) == 0 && projection_.axis(1) == 1 && projection_.axis(2) == 2;
}


void Foam::dcpRBFMotionSolver::insertPrescribed(vectorField& disp) const
{
    for (const label pointi : boundaryMeshPoints_)
    {
        disp[pointi] = prescribed_[pointi];
    }
}


void Foam::dcpRBFMotionSolver::copyValues
(
    const dcprbf::Values& v,
    vectorField& disp
) const
{
    if (rotation_.active())
    {
        forAll(disp, pointi)
        {
            if (boundaryPoints_.kind(pointi) != dcpRBFBoundaryPoints::interiorPoint)
            {
                disp[pointi] = prescribed_[pointi];
            }
            else
            {
                const Eigen::RowVector3d u
                (
                    v.row(distinct_.of(pointi)) + rotation_.displacement().row(pointi)
                );
                disp[pointi] = projection_.fromCore(u.data());
            }
        }
    }
    else
    {
        // projection_.fromCore in one loop: the axes in locals (not
        // reloaded after each store, as the compiler must for char members)
        const label a0 = projection_.axis(0), a1 = projection_.axis(1), a2 = projection_.axis(2);
        const bool threeD = projection_.dim() == 3;
        const dcpRBFBoundaryPoints::pointKind* kind = boundaryPoints_.kinds().cdata();
        const point* prescribed = prescribed_.cdata();
        vector* out = disp.data();
        const label n = disp.size();
        for (label pointi = 0; pointi < n; ++pointi)
        {
            if (kind[pointi] != dcpRBFBoundaryPoints::interiorPoint)
            {
                out[pointi] = prescribed[pointi];
            }
            else
            {
                const double* c = &v(distinct_.of(pointi), 0);
                vector& o = out[pointi];
                o[a0] = c[0];
                o[a1] = c[1];
                o[a2] = threeD ? c[2] : 0.0;
            }
        }
    }
}


Foam::scalar Foam::dcpRBFMotionSolver::interpolateDisplacement
(
    const dcprbf::Values& d
)
{
    pointsMeasured_ = false;

    // evaluated once per distinct point (2D: the front and back twins)
    const dcprbf::RbfEvaluator& s = controlPoints_.evaluator();
    const std::size_t budget = controlPoints_.storageBudget();
    const bool stored = stored_.prepare(s.centres(), budget);
    vectorField& disp = pointDisplacement_.primitiveFieldRef();
    if
    (
        stored && writesRowsToPoints() && disp.size()
     && stored_.evaluateInto
        (
            s.weights(), s.polynomialCoeffs(), interiorTargets_, projection_.dim(),
            &disp[0][0]
        )
    )
    {
        // the control set's matrix is stored (patched or not), the core's
        // axes are the mesh's: one product written straight to the
        // interior points (in 2D to both twins of a distinct point), then
        // the prescribed
        insertPrescribed(disp);
    }
    else
    {
        const dcprbf::Points& x = distinct_.points();
        dcprbf::Values& v = values_;
        v.resize(x.rows(), 3);
        if (stored)
        {
            // the control set's matrix is stored: one product
            stored_.evaluate(s.weights(), s.polynomialCoeffs(), v);
        }
        else
        {
            s.evaluate(x.data(), x.rows(), v.data());
        }
        copyValues(v, disp);
    }
    return correctInterpolated(d);
}


Foam::scalar Foam::dcpRBFMotionSolver::correctInterpolated
(
    const dcprbf::Values& d
)
{
    // Error at the boundary points, blended into the volume
    vectorField& disp = pointDisplacement_.primitiveFieldRef();
    const dcprbf::Values error(d - controlPoints_.boundaryValues());
    if (settings_.boundaryCorrection())
    {
        correction_.apply(error, projection_, disp);
    }
    constrainInterpolated();

    scalar err = 0;
    forAll(boundaryPoints_.moving(), i)
    {
        if (boundaryPoints_.moving()[i]) err = max(err, error.row(i).norm());
    }
    const scalar dMax = d.rows() ? d.rowwise().norm().maxCoeff() : 0;
    return dMax > 0 ? err/dMax : 0;
}


// ************************************************************************* //
