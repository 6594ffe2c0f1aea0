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

    // (motionSolver dcpRBF: selected in dcpRBFVelocityMotionSolver.C, this
    // class or the velocity-driven one as the case is)

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
    // the construction checks, the quality's scan as the swap rule reads
    // it, the set-up report
    const dcpRBFContext& c = context_;
    const dcpRBFQualityRegion& region = quality_.region();
    if (c.settings().scanLowest())
    {
        quality_.measureLowest(swapRule_->lowestCells(region.nChecked()));
    }
    quality_.rankBest(swapRule_->readsBestCells());

    setThreads();
    prescribed_.checkPatches(context_.coeffs());
    checkSetSize();
    checkRegion();

    const dcpRBFSettings& s = c.settings();
    if (!found(typeName + "Coeffs"))
    {
        // and what a former motion solver left (diffusivity, component:
        // read where a component drives the case)
        wordHashSet openfoams
        ({
            "FoamFile", "dynamicFvMesh", "dynamicFvMeshLibs", "motionSolver",
            "motionSolverLibs", "solver", "libs", "cellZone", "cellSet"
        });
        const word driving(dcpRBFSettings::conditionsIn(mesh()).name);
        const bool byComponent =
            driving != "pointDisplacement" && driving != "pointMotionU";
        if (byComponent)
        {
            openfoams.insert("component");
        }
        string others;
        for (const entry& e : *this)
        {
            const word& k = e.keyword();
            const bool componentCoeffs =
                byComponent && e.isDict()
             && k.ends_with("ComponentLaplacianCoeffs");
            if (!openfoams.found(k) && !componentCoeffs)
            {
                others += (others.empty() ? "" : " ") + k;
            }
        }
        Info<< typeName << ": no " << typeName << "Coeffs in " << name()
            << ": every setting at its default";
        if (others.size())
        {
            Info<< " (" << others.c_str() << ": not dcpRBF's keywords, which"
                << " it ignores; a mesh class may read them)";
        }
        Info<< endl;
    }
    Info<< typeName << ": " << c.boundaryPoints().size() << " boundary points ("
        << word(s.kernel().name()) << ", supportRadius "
        << s.kernel().radius()
        << (s.radiusDefault() ? " (not given: the mesh's extent)" : "")
        << ", polynomial "
        << Switch(s.polynomial()) << ", " << c.dim() << "D"
        << (c.projection().wedge() ? " in the wedge's centre plane" : "")
        << ", selection " << s.selection().selectionName()
        << (
               s.selection().selectionGiven || !s.selection().swaps()
             ? "" : " (not given: more boundary points than maxPoints)"
           );
    if (!s.selection().everyCandidate() && s.selection().maxPointsBounded)
    {
        Info<< ", maxPoints " << s.selection().maxPoints
            << " (not given: the greedy basis's budget)";
    }
    Info<< "), "
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
    displacementMotionSolver(withPointDisplacement(mesh, dict), dict, typeName),
    dcpRBFStages
    (
        mesh, *this, coeffDict(), pointDisplacement_, points0(), debug
    ),
    inNewPoints_(false),
    nReusedPoints_(0),
    coeffsAtStart_(context_.coeffs())
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
    dcpRBFStages
    (
        mesh, *this, coeffDict(), pointDisplacement_, this->points0(), debug
    ),
    inNewPoints_(false),
    nReusedPoints_(0),
    coeffsAtStart_(context_.coeffs())
{
    construct();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFMotionSolver::writeLog()
{
    log_.write(step_, quality_.inStep());
}


dcprbf::Values Foam::dcpRBFMotionSolver::prescribe()
{
    // One evaluation of the conditions; the bodies' rigid motions blended,
    // the RBF interpolates the rest
    prescribed_.read();
    dcprbf::Values d(context_.boundaryPoints().gather(prescribed_.values()));
    if (rotation_.active())
    {
        d = rotation_.fit(d);
        rotation_.report(Info);
    }
    return d;
}


bool Foam::dcpRBFMotionSolver::interpolate(const dcprbf::Values& d)
{
    // Select: the set chosen once something moves, solved for d,
    // re-selected while the boundary error is too large (no set: the null
    // interpolant)
    const bool interpolant = controlPoints_.select(d);
    if (interpolant)
    {
        controlPoints_.solve(d);
        step_.nAdded += controlPoints_.reselect(d, step_.atMaxPoints);
    }
    log_.split(&part::select);

    // Interpolate and correct (the boundary snapped, the constraints)
    step_.boundaryError = interpolation_.interpolate(d);
    log_.split(&part::interpolate);
    return interpolant;
}


Foam::scalar Foam::dcpRBFMotionSolver::checkAndSwap
(
    const dcprbf::Values& d,
    const bool interpolant,
    const bool moves
)
{
    // Check: the new mesh's quality, unless nothing moves or the swap rule
    // measures the mesh it keeps itself (one measurement)
    const bool measured =
        moves && (!interpolant || swapRule_->measuresFirst());
    if (measured)
    {
        quality_.measure();
    }
    if (!interpolant)
    {
        return 1;
    }

    // Swap (swapRule errorGuided: trial swaps kept where they help); what
    // a later step's mesh without swaps is compared with is the quality
    // before the guard (dcprbf::TrialSchedule::endWaitIfWorse)
    swapRule_->afterInterpolate(d, step_, measured);
    log_.split(&part::swap);
    const dcpRBFQualityRegion::summary* unguarded = quality_.inStep();
    return unguarded ? unguarded->minQuality : 1;
}


void Foam::dcpRBFMotionSolver::endStep
(
    const dcprbf::Values& d,
    const scalar unguardedMin
)
{
    step_.nControl = controlPoints_.size();
    controlPoints_.endStep();
    swapRule_->endStep(unguardedMin);
    if (mesh().time().writeTime())
    {
        writer_.write(controlPoints_.set(), d);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFMotionSolver::solve()
{
    step_ = dcpRBFStepState();
    quality_.startStep();
    log_.start();

    // Swap before the solve (swapRule nearest: from the mesh as it is)
    swapRule_->beforeSolve(step_);
    log_.split(&part::swap);

    // Prescribe, select, interpolate, check and swap (what the swaps are
    // later judged against: the quality before the guard), guard
    const dcprbf::Values d(prescribe());
    const bool interpolant = interpolate(d);
    const bool moves =
        interpolant || rotation_.active() || prescribed_.selfMoved().size();
    const scalar unguardedMin = checkAndSwap(d, interpolant, moves);
    if (moves)
    {
        guard_.apply(d, step_);
        log_.split(&part::guard);
    }

    // End of step: the set's, the rule's, the control points written
    if (interpolant)
    {
        endStep(d, unguardedMin);
    }

    // The conditions' last word; the measured points stay the new points
    // if it changed nothing (the step's mesh keeps its version)
    prescribed_.finish();
    cellDisplacement_.update();
    log_.split(&part::points);
    if (!inNewPoints_)
    {
        writeLog();
    }
}


Foam::tmp<Foam::pointField> Foam::dcpRBFMotionSolver::curPoints() const
{
    tmp<pointField> tcurPoints(new pointField(points0().size()));
    quality_.currentPoints(tcurPoints.ref());
    frame_.place(tcurPoints.ref());
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
    const pointField& measuredPoints = quality_.lastPoints();
    const bool measured =
        quality_.measured() && measuredPoints.size() == points0().size();
    tmp<pointField> tpoints;
    if (!measured)
    {
        tpoints = curPoints();
    }
    else if (frame_.places())
    {
        tpoints = tmp<pointField>(new pointField(measuredPoints));
        frame_.place(tpoints.ref());
    }
    else
    {
        tpoints = tmp<pointField>(measuredPoints);
    }
    nReusedPoints_ += measured;
    log_.split(&dcpRBFStepLog::times::points);
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
        dcpRBFSettings::changedEntries
        (
            coeffsAtStart_, dcpRBFSettings::coeffsIn(coeffDict())
        )
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
