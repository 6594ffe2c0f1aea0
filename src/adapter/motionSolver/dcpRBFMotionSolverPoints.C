/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFMotionSolver, continued: the step's final constraints on the
    displacement and the new points.
\*---------------------------------------------------------------------------*/

#include "dcpRBFMotionSolver.H"
#include "clockTime.H"

#include <cstring>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFMotionSolver::finishDisplacement()
{
    // The fixed-value conditions' values inserted (not re-evaluated: this
    // completes the step's one evaluation), the constraints applied as
    // pointConstraints::constrainDisplacement does, but for its 2D
    // correction of the displacement: curPoints() corrects the points, so
    // the displacement stays the one the quality was measured for. (In 2D
    // the interior front and back twins have the same displacement by
    // construction: one value per distinct point, the correction by the
    // same nearest boundary point; the boundary points get their prescribed
    // values below, as before.) Then the
    // listed patches' rule, the same on every processor: moving points
    // where prescribed (also where a static patch's condition says
    // otherwise), static points in place
    vectorField& disp = pointDisplacement_.primitiveFieldRef();
    if (pointsMeasured_)
    {
        // the only points this can change
        finishedBefore_.setSize(finishedPoints_.size());
        forAll(finishedPoints_, i)
        {
            finishedBefore_[i] = disp[finishedPoints_[i]];
        }
    }
    pointDisplacement_.setUpToDate();
    pointDisplacement_.storeOldTimes();
    pointVectorField::Boundary& bf = pointDisplacement_.boundaryFieldRef();
    forAll(bf, patchi)
    {
        if (bf[patchi].fixesValue())
        {
            bf[patchi].evaluate();
        }
    }
    constrain();
    insertPrescribed(disp);
    for (label i = 0; pointsMeasured_ && i < finishedPoints_.size(); ++i)
    {
        // bitwise, as the measured points were made
        pointsMeasured_ =
            std::memcmp(&finishedBefore_[i], &disp[finishedPoints_[i]], sizeof(vector)) == 0;
    }
}


void Foam::dcpRBFMotionSolver::currentPoints(pointField& p) const
{
    // points0 + displacement (as Field's operator+), 2D corrected
    twoDPoints_.move(points0(), pointDisplacement_.primitiveField(), p);
}


Foam::tmp<Foam::pointField> Foam::dcpRBFMotionSolver::curPoints() const
{
    tmp<pointField> tcurPoints(new pointField(points0().size()));
    currentPoints(tcurPoints.ref());
    return tcurPoints;
}


Foam::tmp<Foam::pointField> Foam::dcpRBFMotionSolver::newPoints()
{
    {
        // the flag reset however solve() ends (FatalError may throw)
        struct scope
        {
            bool& flag;
            explicit scope(bool& f) : flag(f) { flag = true; }
            ~scope() { flag = false; }
        } inNewPoints(inNewPoints_);
        solve();
    }
    clockTime timer;
    // the points the quality was measured on, if the displacement is the
    // one they were made from, else made anew. The measured ones by
    // reference (OpenFOAM's callers copy them or read them at once)
    const bool measured = pointsMeasured_ && lastPoints_.size() == points0().size();
    tmp<pointField> tpoints
    (
        measured ? tmp<pointField>(lastPoints_) : curPoints()
    );
    nReusedPoints_ += measured;
    step_.pointsTime += timer.elapsedTime();
    log_.write(step_);
    return tpoints;
}


// ************************************************************************* //
