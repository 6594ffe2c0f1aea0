/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFMotionSolver.H"
#include "dcpRBFVersion.H"
#include "dcpRBFThreads.H"
#include "addToRunTimeSelectionTable.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "processorPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "clockTime.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "SimdWidth.hpp"

#include <numeric>

#ifdef _OPENMP
    #include <omp.h>
#endif

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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::string Foam::dcpRBFMotionSolver::selfMovedNames() const
{
    string names;
    for (const label patchi : selfMoved_)
    {
        names += (names.empty() ? "" : " ") + mesh().boundaryMesh()[patchi].name();
    }
    return names;
}


void Foam::dcpRBFMotionSolver::checkPatches()
{
    const polyBoundaryMesh& patches = mesh().boundaryMesh();
    const pointVectorField::Boundary& bf = pointDisplacement_.boundaryField();
    wordList unlisted;
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        if (settings_.movingPatchIDs().found(patchi))
        {
            if (!bf[patchi].fixesValue())
            {
                FatalIOErrorInFunction(coeffDict())
                    << "Keyword movingPatches: patch " << pp.name() << " has"
                    << " the pointDisplacement condition " << bf[patchi].type()
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
        else if
        (
            !settings_.staticPatchIDs().found(patchi)
         && !polyPatch::constraintType(pp.type())
        )
        {
            if (bf[patchi].fixesValue())
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
    if (unlisted.size())
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


void Foam::dcpRBFMotionSolver::checkSetSize() const
{
    const dcpRBFSelectionSettings& sel = settings_.selection();
    if (sel.selection == dcpRBFSelectionSettings::mode::all)
    {
        return;
    }
    const dictionary& dict = coeffDict().subDict("controlPoints");
    const label fewest = settings_.polynomial() ? projection_.dim() + 1 : 1;
    if (sel.maxPoints < fewest)
    {
        FatalIOErrorInFunction(dict)
            << "maxPoints " << sel.maxPoints << " is below the "
            << fewest << " control points the linear polynomial needs in "
            << projection_.dim() << "D: take maxPoints " << fewest
            << " or more (or polynomial false)" << exit(FatalIOError);
    }
    if (sel.minPoints > boundaryPoints_.size())
    {
        FatalIOErrorInFunction(dict)
            << "minPoints " << sel.minPoints << " is above the "
            << boundaryPoints_.size() << " boundary points of movingPatches"
            << " and staticPatches (the candidate control points): take"
            << " minPoints " << boundaryPoints_.size() << " or fewer"
            << " (selection all takes every one)" << exit(FatalIOError);
    }
}


void Foam::dcpRBFMotionSolver::setThreads() const
{
    // MPI ranks x OpenMP threads beyond the cores slows everything down
    // several times: the cores available to the rank, shared among the
    // node's ranks, unless the user says otherwise (dcpRBFThreads)
    #ifdef _OPENMP
    const label nThreads =
        dcpRBFThreads::set(mesh().nPoints(), settings_.pointsPerThread());
    // ranks may differ (their point counts): the range over them
    const label nMin = returnReduce(nThreads, minOp<label>());
    const label nMax = returnReduce(nThreads, maxOp<label>());
    const bool fromEnv = !getEnv("OMP_NUM_THREADS").empty();
    Info<< typeName << ": "
        << (
               nMin == nMax ? Foam::name(nMin)
             : Foam::name(nMin) + "-" + Foam::name(nMax)
           ).c_str()
        << " OpenMP thread(s)" << (Pstream::parRun() ? " per processor" : "")
        << " (" << (
               fromEnv ? string("OMP_NUM_THREADS")
             : settings_.pointsPerThread() > 0
             ? "one per pointsPerThread " + Foam::name(settings_.pointsPerThread())
               + " mesh points, up to the cores available"
             : string("the cores available")
           ).c_str()
        << (fromEnv ? ")" : "; set OMP_NUM_THREADS to change)") << endl;
    #endif
    // the quality kernels' build (the same values on any)
    const string cap(getEnv("DCPRBF_SIMD_WIDTH"));
    if (!cap.empty() && cap.find_first_not_of("0123456789") != std::string::npos)
    {
        FatalErrorInFunction
            << "The environment variable DCPRBF_SIMD_WIDTH is " << cap
            << ": not a width in bits. Allowed: a whole number, e.g. 256"
            << " (at most AVX2) or 128 (no AVX); unset: the widest the"
            << " processor has" << exit(FatalError);
    }
    const unsigned width = dcprbf::SimdWidth::bits();
    Info<< typeName << ": quality kernels in "
        << (width >= 512 ? "AVX-512" : width >= 256 ? "AVX2" : "default")
        << " vectors"
        << (
               getEnv("DCPRBF_SIMD_WIDTH").empty()
             ? " (DCPRBF_SIMD_WIDTH=256 caps them at AVX2)"
             : " (DCPRBF_SIMD_WIDTH " + getEnv("DCPRBF_SIMD_WIDTH") + ")"
           ).c_str()
        << endl;
}


void Foam::dcpRBFMotionSolver::writeControlPoints(const dcprbf::Values& d) const
{
    if (!Pstream::master())
    {
        return;
    }
    const Time& t = mesh().time();
    const fileName dir(t.rootPath()/t.globalCaseName()/"postProcessing"/"dcpRBF");
    mkDir(dir);
    OFstream os(dir/"controlPoints_" + t.timeName() + ".vtk");
    const std::vector<Eigen::Index>& idx = controlPoints_.set().indices();
    os  << "# vtk DataFile Version 2.0" << nl
        << "dcpRBF control points at time " << t.timeName() << nl
        << "ASCII" << nl << "DATASET POLYDATA" << nl
        << "POINTS " << idx.size() << " double" << nl;
    for (const Eigen::Index i : idx)
    {
        const point x0(projection_.pointFromCore(boundaryPoints_.points().row(i).data()));
        const point x(x0 + projection_.fromCore(d.row(i).data()));
        os  << x.x() << ' ' << x.y() << ' ' << x.z() << nl;
    }
    os  << "VERTICES " << idx.size() << ' ' << 2*idx.size() << nl;
    for (std::size_t k = 0; k < idx.size(); ++k) os << "1 " << k << nl;
    os  << "POINT_DATA " << idx.size() << nl
        << "SCALARS moving int 1" << nl << "LOOKUP_TABLE default" << nl;
    for (const Eigen::Index i : idx) os << int(boundaryPoints_.moving()[i]) << nl;
    os  << "SCALARS age int 1" << nl << "LOOKUP_TABLE default" << nl;
    for (const int a : controlPoints_.set().ages()) os << a << nl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

void Foam::dcpRBFMotionSolver::initialise()
{
    setThreads();
    checkPatches();
    checkSetSize();
    if (region_.size() == 0)
    {
        FatalIOErrorInFunction(coeffDict())
            << "supportRadius " << Foam::name(settings_.kernel().radius()).c_str() << " reaches"
            << " no cell centre from the moving patches' points: the cells"
            << " touching them would take the whole motion (and fold as"
            << " soon as it exceeds their size). Take supportRadius several"
            << " times the largest displacement, and at least a few cells"
            << " across (e.g. 5 movingExtent)"
            << exit(FatalIOError);
    }

    // The points finishDisplacement() can change, and the prescribed ones
    // (std::vector: GCC's alloc-size-larger-than on a boolList of nPoints)
    std::vector<char> mark(std::size_t(mesh().nPoints()), false);
    DynamicList<label> prescribed;
    for (label pointi = 0; pointi < mesh().nPoints(); ++pointi)
    {
        if (boundaryPoints_.kind(pointi) != dcpRBFBoundaryPoints::interiorPoint)
        {
            mark[pointi] = true;
            prescribed.append(pointi);
        }
    }
    boundaryMeshPoints_.transfer(prescribed);
    {
        std::vector<std::size_t>& start = interiorTargets_.start;
        start.assign(std::size_t(distinct_.points().rows()) + 1, 0);
        for (label pointi = 0; pointi < mesh().nPoints(); ++pointi)
        {
            if (!mark[pointi]) ++start[std::size_t(distinct_.of(pointi)) + 1];
        }
        std::partial_sum(start.begin(), start.end(), start.begin());
        std::vector<std::size_t> next(start.begin(), start.end() - 1);
        interiorTargets_.point.resize(start.back());
        for (label pointi = 0; pointi < mesh().nPoints(); ++pointi)
        {
            if (!mark[pointi])
            {
                interiorTargets_.point[next[std::size_t(distinct_.of(pointi))]++] = int(pointi);
            }
        }
    }
    for (const polyPatch& pp : mesh().boundaryMesh())
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
    for (label pointi = 0; pointi < mesh().nPoints(); ++pointi)
    {
        if (mark[pointi]) finished.append(pointi);
    }
    finishedPoints_.transfer(finished);
    Info<< typeName << ": " << boundaryPoints_.size() << " boundary points ("
        << word(settings_.kernel().name()) << ", supportRadius "
        << settings_.kernel().radius() << ", polynomial "
        << Switch(settings_.polynomial()) << ", " << projection_.dim()
        << "D, selection "
        << dcpRBFSelectionSettings::modeNames[settings_.selection().selection]
        << "), " << region_.size() << " cells in reach, "
        << region_.nChecked() << " checked at every step (every cell whose"
        << " points can move)" << endl;
}


Foam::dcpRBFMotionSolver::dcpRBFMotionSolver
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    displacementMotionSolver(mesh, dict, typeName)
{
    initialise();
}


Foam::dcpRBFMotionSolver::dcpRBFMotionSolver
(
    const polyMesh& mesh,
    const IOdictionary& dict,
    const pointVectorField& pointDisplacement,
    const pointIOField& points0
)
:
    displacementMotionSolver(mesh, dict, pointDisplacement, points0, typeName)
{
    initialise();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFMotionSolver::solve()
{
    clockTime timer;
    step_ = dcpRBFStepLog::record();
    pointsMeasured_ = false;
    dcpRBFStepLog::record& r = step_;

    // 1. swapRule nearest: swaps from the quality of the mesh as it is
    if (controlPoints_.ready() && controlPoints_.swapsBeforeSolve())
    {
        const dcpRBFQualityRegion::summary& q = currentQuality();
        if (q.minQuality < 1 - 1e-12)
        {
            controlPoints_.swap(q, r.nAdded, r.nRemoved);
        }
    }
    r.swapTime = timer.timeIncrement();

    // 2. This step's boundary displacement (one evaluation of the
    //    conditions); (re)selection
    readPrescribed();
    dcprbf::Values d(boundaryPoints_.gather(prescribed_));
    if (rotation_.active())
    {
        // the bodies' rigid motions blended; the RBF interpolates the rest
        d = rotation_.fit(d);
        rotation_.report(Info);
    }
    if (controlPoints_.select(d))
    {
        controlPoints_.solve(d);
        r.nAdded += controlPoints_.reselect(d, r.atMaxPoints);
        r.selectTime = timer.timeIncrement();

        // 3. Interpolate, snap the boundary; the new mesh's quality (after
        //    the trials when they can do without it: one measurement)
        r.boundaryError = interpolateDisplacement(d);
        r.interpolateTime = timer.timeIncrement();
        const bool measured = !trialsBeforeMeasure();
        if (measured)
        {
            measureQuality(r);
        }
        r.guardTime = timer.timeIncrement();

        // 4. swapRule errorGuided: trial swaps, kept if they help; a
        //    rescue if the mesh without swaps has inverted cells
        //    (waiting after undone ones unless the mesh got worse since)
        const scalar guardBefore = r.guardTime;
        const bool waitEnded =
            measured && controlPoints_.endWaitIfWorse(lastQuality_.minQuality);
        const FixedList<label, 2> schedule(controlPoints_.trialSchedule());
        if
        (
            trySwaps(d, r, measured) == 0
         && !measured
         && lastQuality_.nInverted > 0
        )
        {
            // the mesh without swaps (measured) has inverted cells: the
            // rescue, backing off as if the trials had not been made
            controlPoints_.restoreTrialSchedule(schedule);
            trySwaps(d, r, true);
        }
        r.swapTime += timer.timeIncrement() - (r.guardTime - guardBefore);
        r.waitEnded = waitEnded;
        // (before the guard: what a later step's mesh without swaps is
        // compared with, in endWaitIfWorse)
        const scalar unguardedMin = r.regionMin;

        // 5. Guard the quality
        guardQuality(d, r);
        r.guardTime += timer.timeIncrement();

        r.nControl = controlPoints_.size();
        controlPoints_.endStep(unguardedMin);
        if (mesh().time().writeTime())
        {
            writeControlPoints(d);
        }
    }
    else if (rotation_.active())
    {
        // Rigid bodies: the blended rigid motions alone
        vectorField& disp = pointDisplacement_.primitiveFieldRef();
        forAll(disp, pointi)
        {
            disp[pointi] =
                boundaryPoints_.kind(pointi) == dcpRBFBoundaryPoints::interiorPoint
              ? projection_.fromCore(rotation_.displacement().row(pointi).data())
              : prescribed_[pointi];
        }
        constrainInterpolated();
        r.interpolateTime = timer.timeIncrement();
        measureQuality(r);
        guardQuality(d, r);
        r.guardTime = timer.timeIncrement();
    }
    else
    {
        // Nothing moves yet: every point but the moving ones stays put,
        // unless a patch in neither list is moved by its own condition
        pointDisplacement_.primitiveFieldRef() = prescribed_;
        if (selfMoved_.size())
        {
            constrain();
            measureQuality(r);
            guardQuality(d, r);
            r.guardTime = timer.timeIncrement();
        }
    }

    finishDisplacement();
    r.pointsTime = timer.timeIncrement();
    if (!inNewPoints_)
    {
        log_.write(r);
    }
}


void Foam::dcpRBFMotionSolver::updateMesh(const mapPolyMesh&)
{
    FatalErrorInFunction
        << typeName << " does not support topology changes (mesh refinement,"
        << " layer addition, ...): the control points and reference points"
        << " would no longer match the mesh" << exit(FatalError);
}


// ************************************************************************* //
