/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFControlPoints.H"
#include "GreedySelector.hpp"
#include "dcpRBFPstreamCollective.H"
#include "dcpRBFResidentMemory.H"
#include "Time.H"
#include "dcpRBFVersion.H"

#include <algorithm>
#include <ctime>
#include <iterator>
#include <numeric>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dcpRBFControlPoints, 0);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

std::vector<char> removableFlags(const Foam::boolList& moving)
{
    return std::vector<char>(moving.begin(), moving.end());
}

dcprbf::DynamicControlSet::Options setOptions(const Foam::dcpRBFSelectionSettings& s)
{
    dcprbf::DynamicControlSet::Options o;
    o.minPoints = s.everyCandidate() ? 0 : s.minPoints;
    o.maxPoints =
        s.everyCandidate() ? std::numeric_limits<Eigen::Index>::max() : s.maxPoints;
    o.protectSteps = s.protectSteps;
    return o;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFControlPoints::greedy(const dcprbf::Values& d)
{
    const dcpRBFSelectionSettings& s = settings_.selection();
    dcprbf::Values target(d);
    if (s.selectOn == dcpRBFSelectionSettings::target::unit)
    {
        const Eigen::RowVector3d u
        (
            dim_ == 3 ? Eigen::RowVector3d(1, 1, 1)/std::sqrt(3.0)
                      : Eigen::RowVector3d(1, 1, 0)/std::sqrt(2.0)
        );
        forAll(boundary_.moving(), i)
        {
            target.row(i) = boundary_.moving()[i] ? u : Eigen::RowVector3d::Zero();
        }
    }
    dcprbf::GreedyOptions o;
    o.tolerance = s.tolerance;
    o.minPoints = s.minPoints;
    o.maxPoints = s.maxPoints;
    o.doubleEdged = s.doubleEdged;
    const dcprbf::GreedySelector g(settings_.kernel(), settings_.polynomial(), dim_, o);
    // In parallel the selection's candidates (and its Nb x N basis) are
    // divided over the processors, in blocks of the global set's canonical
    // order: the same result as in serial, on every processor
    const label n = block_.end() - block_.begin();
    const dcprbf::Values t(target.middleRows(block_.begin(), n));
    const dcpRBFPstreamCollective comm;
    const dcpRBFResidentMemory memory;
    const std::clock_t cpu0 = std::clock();
    dcprbf::GreedyResult r(g.select(dcprbf::CandidateRows(comm, block_.points(), t)));
    if (debug)
    {
        // the processor's own time: a wall time is no speed-up where more
        // processes than cores share them
        scalar cpu = scalar(std::clock() - cpu0)/CLOCKS_PER_SEC;
        scalar most = memory.peakAboveStartMB();
        scalar least = most;
        reduce(cpu, maxOp<scalar>());
        reduce(most, maxOp<scalar>());
        reduce(least, minOp<scalar>());
        Info<< "dcpRBF: greedy selection over " << Pstream::nProcs()
            << " processor(s), peak resident memory above its start [MB]:"
            << " largest " << most << ", smallest " << least
            << "; CPU time [s], largest " << cpu << endl;
    }
    Info<< "dcpRBF: greedy selection of " << r.selected.size() << " of "
        << boundary_.size() << " boundary points, relative error "
        << r.historyError.back() << (r.converged ? "" : " (tolerance not met)")
        << endl;
    if (r.dependent)
    {
        WarningInFunction
            << "The greedy selection stopped at " << r.selected.size()
            << " points, relative error " << r.historyError.back()
            << " (tolerance " << s.tolerance << "): the next point is"
            << " numerically dependent on those selected (the kernel matrix"
            << " singular to round-off with it). supportRadius "
            << settings_.kernel().radius() << " is large against the"
            << " spacing of the boundary points: a smaller supportRadius lets"
            << " the set fit the boundary better" << endl;
    }
    // The greedy's factorization is taken over (same candidates, frame and
    // kernel): no O(N^3) refactorization
    set_.reset(r.selected, std::move(*r.factorization));
    updated_ = true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFControlPoints::dcpRBFControlPoints(const dcpRBFContext& context)
:
    settings_(context.settings()),
    boundary_(context.boundaryPoints()),
    dim_(context.dim()),
    set_
    (
        boundary_.points(),
        removableFlags(boundary_.moving()),
        settings_.kernel(),
        settings_.polynomial(),
        dim_,
        setOptions(settings_.selection())
    ),
    time_(context.time()),
    ready_(false),
    restored_(false),
    updated_(false),
    warnedMaxPoints_(false),
    blend_(nullptr),
    selectedWith_(selectedWith(context, boundary_.size())),
    state_
    (
        "dcpRBFState", context.mesh(),
        [this](dictionary& state) { storeState(state); }
    ),
    block_(boundary_, settings_.kernel(), set_.evaluator().polynomial())
{
    try
    {
        ready_ = restored_ = readState();
        if (!ready_ && settings_.selection().everyCandidate())
        {
            std::vector<Eigen::Index> all(boundary_.size());
            std::iota(all.begin(), all.end(), 0);
            set_.reset(all);
            ready_ = true;
        }
    }
    catch (const dcprbf::Error& e)
    {
        FatalErrorInFunction
            << "Cannot build the RBF system on the " << boundary_.size()
            << " boundary points of movingPatches and staticPatches: "
            << e.what() << nl << "    " << whatToDo(e).c_str()
            << exit(FatalError);
    }
}


bool Foam::dcpRBFControlPoints::select(const dcprbf::Values& d)
{
    if (ready_)
    {
        return true;
    }
    const bool unit = settings_.selection().selectOn == dcpRBFSelectionSettings::target::unit;
    if (!unit && (d.rows() == 0 || d.cwiseAbs().maxCoeff() == 0))
    {
        return false;   // nothing moves yet
    }
    try
    {
        greedy(d);
    }
    catch (const dcprbf::Error& e)
    {
        FatalErrorInFunction
            << "Greedy selection failed: " << e.what() << nl
            << "    " << whatToDo(e).c_str() << exit(FatalError);
    }
    ready_ = true;
    return true;
}


void Foam::dcpRBFControlPoints::solve(const dcprbf::Values& d)
{
    try
    {
        if (blend_ && blend_->active())
        {
            set_.solveBlended(d, blend_->from(), blend_->weight());
        }
        else
        {
            set_.solve(d);
        }
    }
    catch (const dcprbf::Error& e)
    {
        FatalErrorInFunction
            << "RBF solve failed: " << e.what() << nl
            << "    " << whatToDo(e).c_str() << exit(FatalError);
    }
}


Foam::scalar Foam::dcpRBFControlPoints::boundaryError
(
    const dcprbf::Values& d,
    label& worst
) const
{
    const scalar err =
        block_.largestMovingError(set_.evaluator(), d, storageBudget()/16, worst);
    return dcprbf::relativeToLargest(err, d, settings_.kernel().radius());
}


dcprbf::Values Foam::dcpRBFControlPoints::blockValues() const
{
    return block_.atBlock(set_.evaluator(), storageBudget()/16);
}


Foam::label Foam::dcpRBFControlPoints::reselect
(
    const dcprbf::Values& d,
    bool& atMaxPoints
)
{
    atMaxPoints = false;
    if (settings_.selection().everyCandidate())
    {
        return 0;
    }
    const scalar tol = settings_.selection().reselectTolerance;
    label nAdded = 0;
    label worst = -1;
    scalar err = 0;
    while ((err = boundaryError(d, worst)) > tol)
    {
        if (set_.size() >= settings_.selection().maxPoints)
        {
            atMaxPoints = true;
            break;
        }
        try
        {
            if (worst < 0 || set_.contains(worst) || !set_.add(worst)) break;
        }
        catch (const dcprbf::Error&)
        {
            break;   // numerically dependent: the error is round-off level
        }
        ++nAdded;
        updated_ = true;
        solve(d);
    }
    if (atMaxPoints && !warnedMaxPoints_)
    {
        warnedMaxPoints_ = true;
        WarningInFunction
            << "Time " << time_.timeName() << ": " << set_.size()
            << " control points (maxPoints) and the moving-boundary error "
            << err << " is still above reselectTolerance " << tol << nl
            << "    The boundary is reproduced less accurately than asked;"
            << " raise controlPoints/maxPoints or reselectTolerance. Steps"
            << " where this holds are marked in the log line and dcpRBF.dat;"
            << " this warning is given once." << endl;
    }
    return nAdded;
}


bool Foam::dcpRBFControlPoints::addNear
(
    const dcpRBFRankedCell& cell
)
{
    if (set_.addNearest(cell.centre()) < 0)
    {
        return false;
    }
    updated_ = true;
    return true;
}


std::size_t Foam::dcpRBFControlPoints::storageBudget() const
{
    // evaluationMemoryMB unset: a matrix is worth storing where it is
    // reused, i.e. the set settled: within a patch of the last step's
    // (a set that grows or moves by more at every step costs a build per
    // step and the memory, for nothing: OpenFOAM's SnakeRiverCanyon)
    if (settings_.evaluationMemoryAuto() && !settled_)
    {
        return 0;
    }
    return std::size_t(settings_.evaluationMemoryMB()) << 20;
}


void Foam::dcpRBFControlPoints::endStep()
{
    {
        // settled: at most a patch's centres in or out since the last step
        std::vector<Eigen::Index> now(set_.indices());
        std::sort(now.begin(), now.end());
        std::vector<Eigen::Index> changed;
        std::set_symmetric_difference
        (
            now.begin(), now.end(), lastIndices_.begin(), lastIndices_.end(),
            std::back_inserter(changed)
        );
        settled_ =
            !lastIndices_.empty()
         && changed.size() <= std::size_t(2*dcprbf::StoredEvaluation::maxPatchColumns);
        lastIndices_ = std::move(now);
    }
    set_.nextStep();
    if (time_.writeTime() && updated_)
    {
        // refactorized from the indices, as a restart does (restarts are
        // exact); where a fresh factorization fails to round-off (a set
        // grown point by point past what it would take at once), the
        // incremental one is kept: the run goes on, a restart from here
        // meets the same refusal and says so
        try
        {
            set_.refactorize();
            updated_ = false;
        }
        catch (const dcprbf::Error& e)
        {
            WarningInFunction
                << "Time " << time_.timeName() << ": the control set could not"
                << " be refactorized from its indices (" << e.what() << "); the"
                << " run goes on with its updated factorization, but a restart"
                << " from this time will fail: " << whatToDo(e).c_str() << endl;
        }
    }
}


// ************************************************************************* //
