/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFMotionSolver.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dcpRBFMotionSolver, 0);

    addToRunTimeSelectionTable
    (
        motionSolver,
        dcpRBFMotionSolver,
        dictionary
    );

    addToRunTimeSelectionTable
    (
        displacementMotionSolver,
        dcpRBFMotionSolver,
        displacement
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

void Foam::dcpRBFMotionSolver::construct()
{
    context_.reset
    (
        new dcpRBFContext
        (
            mesh(), *this, coeffDict(), pointDisplacement_, points0(), debug
        )
    );
    const dcpRBFContext& c = *context_;
    controlPoints_.reset(new dcpRBFControlPoints(c));
    rotation_.reset(new dcpRBFRotation(c));
    quality_.reset(new dcpRBFQualityMeasurement(c, rotation_->active()));
    log_.reset(new dcpRBFStepLog(c.time()));
    writer_.reset
    (
        new dcpRBFControlPointsWriter
        (
            c.time(), c.projection(), c.boundaryPoints()
        )
    );
    prescribed_.reset(new dcpRBFPrescribedDisplacement(c));
    interpolation_.reset
    (
        new dcpRBFInterpolation(c, *controlPoints_, *rotation_, *prescribed_)
    );
    frame_.reset(new dcpRBFFrame(c));
    cellDisplacement_.reset(new dcpRBFCellDisplacement(pointDisplacement_));
    swapRule_ = dcpRBFSwapRule::New
    (
        c, *controlPoints_, *quality_, *interpolation_
    );
    guard_.reset
    (
        new dcpRBFQualityGuard(c, *controlPoints_, *interpolation_, *quality_)
    );

    const dcpRBFQualityRegion& region = quality_->region();
    if (c.settings().scanLowest())
    {
        quality_->measureLowest(swapRule_->lowestCells(region.nChecked()));
    }
    quality_->rankBest(swapRule_->readsBestCells());

    setThreads();
    prescribed_->checkPatches(coeffDict());
    checkSetSize();
    checkRegion();

    const dcpRBFSettings& s = c.settings();
    Info<< typeName << ": " << c.boundaryPoints().size() << " boundary points ("
        << word(s.kernel().name()) << ", supportRadius "
        << s.kernel().radius() << ", polynomial "
        << Switch(s.polynomial()) << ", " << c.dim()
        << "D, selection " << s.selection().selectionName() << "), "
        << region.size() << " cells in reach, " << region.nChecked()
        << " checked at every step (every cell whose points can move)"
        << endl;
}


Foam::dcpRBFMotionSolver::dcpRBFMotionSolver
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    displacementMotionSolver(withPointDisplacement(mesh), dict, typeName),
    memory_(debug),
    inNewPoints_(false),
    nReusedPoints_(0),
    coeffsAtStart_(coeffDict())
{
    construct();
}


Foam::dcpRBFMotionSolver::dcpRBFMotionSolver
(
    const polyMesh& mesh,
    const IOdictionary& dict,
    const pointVectorField& pointDisplacement,
    const pointIOField& points0
)
:
    displacementMotionSolver(mesh, dict, pointDisplacement, points0, typeName),
    memory_(debug),
    inNewPoints_(false),
    nReusedPoints_(0),
    coeffsAtStart_(coeffDict())
{
    construct();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFMotionSolver::moveWithControlPoints
(
    const dcprbf::Values& d
)
{
    typedef dcpRBFStepTimer::times part;
    dcpRBFStepState& step = step_;

    // Select: the set solved for d, re-selected while the boundary error
    // is too large
    controlPoints_->solve(d);
    step.nAdded += controlPoints_->reselect(d, step.atMaxPoints);
    timer_->split(&part::select);

    // Interpolate and correct (the boundary snapped, the constraints)
    quality_->changed();
    step.boundaryError = interpolation_->interpolate(d);
    timer_->split(&part::interpolate);
    if (debug)
    {
        memory_.report
        (
            interpolation_->storedBytes(), controlPoints_->block().storedBytes()
        );
    }

    // Check: the new mesh's quality, unless the swap rule measures the
    // mesh it keeps itself (one measurement)
    const bool measured = swapRule_->measuresFirst();
    if (measured)
    {
        quality_->measure();
    }
    timer_->split(&part::guard);

    // Swap (swapRule errorGuided: trial swaps kept where they help)
    swapRule_->afterInterpolate(d, step, measured);
    timer_->split(&part::swap);
    // (before the guard: what a later step's mesh without swaps is
    // compared with, dcprbf::TrialSchedule::endWaitIfWorse)
    const dcpRBFQualityRegion::summary* unguarded = quality_->inStep();
    const scalar unguardedMin = unguarded ? unguarded->minQuality : 1;

    // Guard
    guard_->apply(d, step);
    timer_->split(&part::guard);

    step.nControl = controlPoints_->size();
    controlPoints_->endStep();
    swapRule_->endStep(unguardedMin);
    if (mesh().time().writeTime())
    {
        writer_->write(controlPoints_->set(), d);
    }
}


void Foam::dcpRBFMotionSolver::writeLog()
{
    log_->write(step_, quality_->inStep(), timer_->elapsed());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFMotionSolver::solve()
{
    typedef dcpRBFStepTimer::times part;
    step_ = dcpRBFStepState();
    quality_->startStep();
    timer_.reset(new dcpRBFStepTimer(*quality_));

    // Swap before the solve (swapRule nearest: from the mesh as it is)
    swapRule_->beforeSolve(step_);
    timer_->split(&part::swap);

    // Prescribe: the step's boundary displacement (one evaluation of the
    // conditions)
    prescribed_->read();
    dcprbf::Values d(context_->boundaryPoints().gather(prescribed_->values()));
    if (rotation_->active())
    {
        // the bodies' rigid motions blended; the RBF interpolates the rest
        d = rotation_->fit(d);
        rotation_->report(Info);
    }

    if (controlPoints_->select(d))
    {
        moveWithControlPoints(d);
    }
    else if (rotation_->active())
    {
        // Rigid bodies: the blended rigid motions alone
        interpolation_->rigid();
        timer_->split(&part::interpolate);
        quality_->measure();
        guard_->apply(d, step_);
        timer_->split(&part::guard);
    }
    else
    {
        // Nothing moves yet: every point but the moving ones stays put,
        // unless a patch in neither list is moved by its own condition
        pointDisplacement_.primitiveFieldRef() = prescribed_->values();
        if (prescribed_->selfMoved().size())
        {
            prescribed_->constrain();
            quality_->measure();
            guard_->apply(d, step_);
            timer_->split(&part::guard);
        }
    }

    // The conditions' last word; the measured points stay the new points
    // if it changed nothing
    if (!prescribed_->finish(quality_->measured()))
    {
        quality_->changed();
    }
    cellDisplacement_->update();
    timer_->split(&part::points);
    if (!inNewPoints_)
    {
        writeLog();
    }
}


Foam::tmp<Foam::pointField> Foam::dcpRBFMotionSolver::curPoints() const
{
    tmp<pointField> tcurPoints(new pointField(points0().size()));
    quality_->currentPoints(tcurPoints.ref());
    frame_->place(tcurPoints.ref());
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
    // the points the quality was measured on, if the displacement is the
    // one they were made from, else made anew. The measured ones by
    // reference (OpenFOAM's callers copy them or read them at once)
    const pointField& measuredPoints = quality_->lastPoints();
    const bool measured =
        quality_->measured() && measuredPoints.size() == points0().size();
    tmp<pointField> tpoints;
    if (!measured)
    {
        tpoints = curPoints();
    }
    else if (frame_->places())
    {
        tpoints = tmp<pointField>(new pointField(measuredPoints));
        frame_->place(tpoints.ref());
    }
    else
    {
        tpoints = tmp<pointField>(measuredPoints);
    }
    nReusedPoints_ += measured;
    timer_->split(&dcpRBFStepTimer::times::points);
    writeLog();
    return tpoints;
}


bool Foam::dcpRBFMotionSolver::read()
{
    if (!displacementMotionSolver::read())
    {
        return false;
    }
    const string changes
    (
        dcpRBFSettings::changedEntries(coeffsAtStart_, coeffDict())
    );
    if (changes.size())
    {
        WarningInFunction
            << typeName << "Coeffs changed while running (" << changes.c_str()
            << "): dcpRBF reads its settings when the run starts, and this"
            << " run goes on with those. To use the new ones, stop the run and"
            << " restart it from a written time (the control set is then"
            << " selected anew where they change it)." << endl;
    }
    return true;
}


void Foam::dcpRBFMotionSolver::updateMesh(const mapPolyMesh&)
{
    FatalErrorInFunction
        << typeName << " does not support topology changes (mesh refinement,"
        << " layer addition, ...): the control points and reference points"
        << " would no longer match the mesh" << exit(FatalError);
}


// ************************************************************************* //
