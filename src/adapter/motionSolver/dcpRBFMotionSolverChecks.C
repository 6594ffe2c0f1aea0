/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFMotionSolver, continued: the checks at construction (the point
    displacement field, the set's size, the radius's reach) and the threads.
\*---------------------------------------------------------------------------*/

#include "dcpRBFMotionSolver.H"
#include "dcpRBFThreads.H"
#include "OSspecific.H"
#include "SimdWidth.hpp"
#include "pointFields.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::polyMesh& Foam::dcpRBFMotionSolver::withPointDisplacement
(
    const polyMesh& mesh,
    const dictionary& dict
)
{
    if (!inTime<vector>(mesh, "pointDisplacement"))
    {
        FatalErrorInFunction
            << typeName << " reads the boundary's motion from the point"
            << " displacement field pointDisplacement (a pointVectorField:"
            << " fixedValue, angularOscillatingDisplacement,"
            << " solidBodyMotionDisplacement, ... on the moving patches)"
            << " or, in a velocity solver's case, from the point velocity"
            << " pointMotionU (a pointVectorField), or from one component"
            << " of either (pointMotionUx, pointDisplacementy, ... with the"
            << " keyword component, as the component solvers read them), and"
            << " there is none of them in " << mesh.time().timeName() << "/."
            << exit(FatalError);
    }
    if (inTime<vector>(mesh, "pointMotionU"))
    {
        Info<< typeName << ": pointDisplacement and pointMotionU in "
            << mesh.time().timeName() << "/: the displacement drives the"
            << " motion, the velocity is not read" << endl;
    }
    return mesh;
}


void Foam::dcpRBFMotionSolver::checkSetSize() const
{
    const dcpRBFSelectionSettings& sel = settings().selection();
    if (sel.everyCandidate())
    {
        return;
    }
    const dictionary dict(context_.coeffs().subOrEmptyDict("controlPoints"));
    const label dim = context_.dim();
    const label fewest = settings().polynomial() ? dim + 1 : 1;
    if (sel.maxPoints < fewest)
    {
        FatalIOErrorInFunction(dict)
            << "maxPoints " << sel.maxPoints << " is below the "
            << fewest << " control points the linear polynomial needs in "
            << dim << "D: take maxPoints " << fewest
            << " or more (or polynomial false)" << exit(FatalIOError);
    }
    if (sel.minPoints > context_.boundaryPoints().size())
    {
        FatalIOErrorInFunction(dict)
            << "minPoints " << sel.minPoints << " is above the "
            << context_.boundaryPoints().size() << " boundary points of movingPatches"
            << " and staticPatches (the candidate control points): take"
            << " minPoints " << context_.boundaryPoints().size() << " or fewer"
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
        dcpRBFThreads::set(mesh().nPoints(), settings().pointsPerThread());
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
             : settings().pointsPerThread() > 0
             ? "one per pointsPerThread " + Foam::name(settings().pointsPerThread())
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


void Foam::dcpRBFMotionSolver::checkRegion() const
{
    // (no moving patch: a solid-body frame alone, nothing to reach)
    if (quality_.region().size() == 0 && settings().movingPatchIDs().size())
    {
        FatalIOErrorInFunction(context_.coeffs())
            << "supportRadius " << Foam::name(settings().kernel().radius()).c_str() << " reaches"
            << " no cell centre from the moving patches' points: the cells"
            << " touching them would take the whole motion (and fold as"
            << " soon as it exceeds their size). Take supportRadius several"
            << " times the largest displacement, and at least a few cells"
            << " across (e.g. 5 movingExtent)"
            << exit(FatalIOError);
    }
}


// ************************************************************************* //
