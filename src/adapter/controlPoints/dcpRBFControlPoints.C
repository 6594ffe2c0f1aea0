/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFControlPoints.H"
#include "GreedySelector.hpp"
#include "Time.H"
#include "dcpRBFVersion.H"

#include <algorithm>
#include <iterator>
#include <numeric>

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
    o.minPoints = s.selection == Foam::dcpRBFSelectionSettings::mode::all ? 0 : s.minPoints;
    o.maxPoints =
        s.selection == Foam::dcpRBFSelectionSettings::mode::all
      ? std::numeric_limits<Eigen::Index>::max() : s.maxPoints;
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
    dcprbf::GreedyResult r(g.select(boundary_.points(), target));
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


Foam::dictionary Foam::dcpRBFControlPoints::selectedWith
(
    const polyMesh& mesh,
    const dcpRBFSettings& settings,
    const label nCandidates
)
{
    const auto names = [&](const labelList& ids)
    {
        wordList sorted(ids.size());
        forAll(ids, i)
        {
            sorted[i] = mesh.boundaryMesh()[ids[i]].name();
        }
        Foam::sort(sorted);
        string s;
        for (const word& name : sorted)
        {
            s += (s.empty() ? "" : " ") + name;
        }
        return "(" + s + ")";
    };
    const dcpRBFSelectionSettings& sel = settings.selection();
    dictionary d;
    // as strings: written quoted, read back as written
    const auto put = [&](const word& key, const std::string& value)
    {
        d.set(key, string(value));
    };
    put("movingPatches", names(settings.movingPatchIDs()));
    put("staticPatches", names(settings.staticPatchIDs()));
    put("boundaryPoints", Foam::name(nCandidates));
    put("function", settings.kernel().name());
    put("supportRadius", Foam::name(settings.kernel().radius()));
    put("polynomial", Switch(settings.polynomial()).c_str());
    put("selection", dcpRBFSelectionSettings::modeNames[sel.selection]);
    if (sel.selection != dcpRBFSelectionSettings::mode::all)
    {
        put("tolerance", Foam::name(sel.tolerance));
        put("minPoints", Foam::name(sel.minPoints));
        put("maxPoints", Foam::name(sel.maxPoints));
        put("doubleEdged", Switch(sel.doubleEdged).c_str());
        put("selectOn", dcpRBFSelectionSettings::targetNames[sel.selectOn]);
    }
    return d;
}


Foam::string Foam::dcpRBFControlPoints::changedSettings() const
{
    const dictionary* was = state_.findDict("selectedWith");
    string changes;
    const auto add = [&](const string& what)
    {
        changes += (changes.empty() ? "" : ", ") + what;
    };
    if (!was)
    {
        // a state written before the settings were kept: the boundary's
        // size alone can be checked
        for (const label i : state_.get<labelList>("indices"))
        {
            if (i < 0 || i >= boundary_.size())
            {
                add
                (
                    "the boundary points (a control point's index " + Foam::name(i)
                  + " beyond this run's " + Foam::name(boundary_.size()) + ")"
                );
                break;
            }
        }
        return changes;
    }
    for (const entry& e : selectedWith_)
    {
        const word& key = e.keyword();
        const string now(selectedWith_.get<string>(key));
        const string before(was->getOrDefault<string>(key, "(none)"));
        if (now != before)
        {
            add(key + " " + before + " -> " + now);
        }
    }
    for (const entry& e : *was)
    {
        if (!selectedWith_.found(e.keyword()))
        {
            add(e.keyword() + " " + was->get<string>(e.keyword()) + " -> (none)");
        }
    }
    return changes;
}


void Foam::dcpRBFControlPoints::storeState(dictionary& state) const
{
    state.set("selectedWith", selectedWith_);
    state.set("ready", ready_);
    state.set("trialWait", trialWait_);
    state.set("trialBackoff", trialBackoff_);
    state.set("trialQuality", trialQuality_);
    state.set("indices", dcpRBFCompat::makeList<label>(set_.indices()));
    state.set("ages", dcpRBFCompat::makeList<label>(set_.ages()));
    if (blendFrom_)
    {
        state.set("blendStep", blendStep_);
        state.set("blendFromIndices", dcpRBFCompat::makeList<label>(blendFrom_->indices));
        state.set("blendFromAges", dcpRBFCompat::makeList<label>(blendFrom_->ages));
    }
    else
    {
        state.remove("blendStep");
        state.remove("blendFromIndices");
        state.remove("blendFromAges");
    }
}


bool Foam::dcpRBFControlPoints::readState()
{
    if (!state_.found("indices") || !state_.get<bool>("ready"))
    {
        return false;
    }
    const string changes(changedSettings());
    if (!changes.empty())
    {
        WarningInFunction
            << "The restart state " << state_.objectPath() << " was selected"
            << " with other settings: " << changes.c_str() << "." << nl
            << "    The control set is selected anew (at the first step with"
            << " motion, as at the start of a run) and the error-guided"
            << " trials' schedule starts over: the run does not continue"
            << " the one that wrote the state exactly. To continue it"
            << " exactly, restart with the settings it was written with."
            << endl;
        return false;
    }
    const labelList indices(state_.get<labelList>("indices"));
    const labelList ages(state_.get<labelList>("ages"));
    set_.reset(std::vector<Eigen::Index>(indices.begin(), indices.end()));
    set_.setAges(std::vector<int>(ages.begin(), ages.end()));
    trialWait_ = state_.getOrDefault<label>("trialWait", 0);
    trialBackoff_ = state_.getOrDefault<label>
    (
        "trialBackoff",
        settings_.selection().trialBackoff
    );
    trialQuality_ = state_.getOrDefault<scalar>("trialQuality", 1);
    if (state_.found("blendStep"))
    {
        blendStep_ = state_.get<label>("blendStep");
        const labelList from(state_.get<labelList>("blendFromIndices"));
        const labelList fromAges(state_.get<labelList>("blendFromAges"));
        blendFrom_.reset
        (
            new dcprbf::DynamicControlSet::State
            (
                set_.freshState
                (
                    std::vector<Eigen::Index>(from.begin(), from.end()),
                    std::vector<int>(fromAges.begin(), fromAges.end())
                )
            )
        );
    }
    Info<< "dcpRBF: restarting with " << set_.size() << " control points from "
        << state_.objectPath() << endl;
    return true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFControlPoints::dcpRBFControlPoints
(
    const polyMesh& mesh,
    const dcpRBFSettings& settings,
    const dcpRBFBoundaryPoints& boundary,
    const label dim
)
:
    settings_(settings),
    boundary_(boundary),
    dim_(dim),
    set_
    (
        boundary.points(),
        removableFlags(boundary.moving()),
        settings.kernel(),
        settings.polynomial(),
        dim,
        setOptions(settings.selection())
    ),
    time_(mesh.time()),
    ready_(false),
    updated_(false),
    warnedMaxPoints_(false),
    nKept_(0),
    leaving_(Eigen::RowVector3d::Zero()),
    leavingReach_(0),
    blendStep_(0),
    trialWait_(0),
    trialBackoff_(settings.selection().trialBackoff),
    trialQuality_(1),
    backedOff_(false),
    selectedWith_(selectedWith(mesh, settings, boundary.size())),
    state_
    (
        "dcpRBFState", mesh,
        [this](dictionary& state) { storeState(state); }
    ),
    boundaryStored_
    (
        settings.kernel(), set_.evaluator().polynomial(), boundary.points()
    )
{
    forAll(boundary_.moving(), i)
    {
        if (boundary_.moving()[i]) movingIndex_.push_back(i);
    }
    movingPoints_.resize(Eigen::Index(movingIndex_.size()), 3);
    for (std::size_t k = 0; k < movingIndex_.size(); ++k)
    {
        movingPoints_.row(k) = boundary_.points().row(movingIndex_[k]);
    }
    try
    {
        ready_ = readState();
        if (!ready_ && settings_.selection().selection == dcpRBFSelectionSettings::mode::all)
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


Foam::string Foam::dcpRBFControlPoints::whatToDo(const dcprbf::Error& e) const
{
    const std::string what(e.what());
    const dcprbf::RadialKernel& k = settings_.kernel();
    const string radius(" (supportRadius " + Foam::name(k.radius()) + ")");
    if
    (
        what.find("not positive definite") != std::string::npos
     || what.find("numerically dependent") != std::string::npos
    )
    {
        if (!k.compact())
        {
            return
                "function " + k.name() + " is global: supportRadius is its"
                " shape length" + radius + ", and its matrix is singular to"
                " round-off when that is large against the spacing of the"
                " boundary points. Take supportRadius of a few spacings of"
                " the boundary points, or a compactly supported function"
                " (function WendlandC2; supportRadius several times the"
                " largest displacement)";
        }
        return
            "the kernel matrix is singular to round-off: supportRadius"
          + radius + " is very large against the spacing of the boundary"
            " points (take selection greedy, which selects the points the"
            " interpolant needs, or a smaller supportRadius), or two"
            " boundary points of movingPatches and staticPatches coincide"
            " (a patch listed twice under other names or groups, or the two"
            " sides of an interface: list each once)";
    }
    if
    (
        what.find("collinear") != std::string::npos
     || what.find("coplanar") != std::string::npos
    )
    {
        return
            "the candidates are the points of movingPatches and"
            " staticPatches; with the polynomial they must span the space"
            " (not all on one line in 2D, not all in one plane in 3D): add a"
            " patch off that plane to staticPatches, or set polynomial false";
    }
    return "check movingPatches, staticPatches and controlPoints";
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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
        if (blendFrom_)
        {
            const scalar w =
                scalar(blendStep_)/settings_.selection().swapBlendSteps;
            set_.solveBlended(d, *blendFrom_, w);
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
    // stored: at every candidate, one product; else the moving ones alone
    const dcprbf::RbfEvaluator& ev = set_.evaluator();
    const bool all = storedBoundary();
    dcprbf::Values s;
    if (all)
    {
        boundaryStored_.evaluate(ev.weights(), ev.polynomialCoeffs(), s);
    }
    else
    {
        s = ev.evaluate(movingPoints_);
    }
    scalar err = 0;
    worst = -1;
    for (std::size_t k = 0; k < movingIndex_.size(); ++k)
    {
        const Eigen::Index i = movingIndex_[k];
        const scalar e = (s.row(all ? i : Eigen::Index(k)) - d.row(i)).norm();
        if (e > err)
        {
            err = e;
            worst = label(i);
        }
    }
    const scalar dMax = d.rows() ? d.rowwise().norm().maxCoeff() : 0;
    return dMax > 0 ? err/dMax : 0;
}


bool Foam::dcpRBFControlPoints::storedBoundary() const
{
    return boundaryStored_.prepare(set_.evaluator().centres(), storageBudget()/16);
}


dcprbf::Values Foam::dcpRBFControlPoints::boundaryValues() const
{
    const dcprbf::RbfEvaluator& s = set_.evaluator();
    if (!storedBoundary())
    {
        return s.evaluate(boundary_.points());
    }
    dcprbf::Values v;
    boundaryStored_.evaluate(s.weights(), s.polynomialCoeffs(), v);
    return v;
}


bool Foam::dcpRBFControlPoints::swapsBeforeSolve() const
{
    const dcpRBFSelectionSettings& s = settings_.selection();
    return
        s.selection == dcpRBFSelectionSettings::mode::dynamic
     && s.swapRule == dcpRBFSelectionSettings::rule::nearest;
}


Foam::label Foam::dcpRBFControlPoints::reselect
(
    const dcprbf::Values& d,
    bool& atMaxPoints
)
{
    atMaxPoints = false;
    if (settings_.selection().selection == dcpRBFSelectionSettings::mode::all)
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


void Foam::dcpRBFControlPoints::swap
(
    const dcpRBFQualityRegion::summary& q,
    label& nAdded,
    label& nRemoved
)
{
    nAdded = 0;
    nRemoved = 0;
    const dcpRBFSelectionSettings& s = settings_.selection();
    if (s.selection != dcpRBFSelectionSettings::mode::dynamic || s.swapRule != dcpRBFSelectionSettings::rule::nearest)
    {
        return;
    }
    const auto leaveNear = [&](const dcpRBFQualityRegion::rankedCell& c)
    {
        const Eigen::RowVector3d x(c[1], c[2], c[3]);
        if (set_.removeNearest(x) < 0) return false;
        updated_ = true;
        return true;
    };
    const label n = min(s.nSwap, min(q.worst.size(), q.best.size()));
    for (label k = 0; k < n; ++k)
    {
        if (set_.size() < s.maxPoints)
        {
            nAdded += addNear(q.worst[k]);
            nRemoved += leaveNear(q.best[k]);
        }
        else if
        (
            // at maxPoints: both in one update, at constant size
            set_.swapNearest
            (
                Eigen::RowVector3d(q.worst[k][1], q.worst[k][2], q.worst[k][3]),
                Eigen::RowVector3d(q.best[k][1], q.best[k][2], q.best[k][3])
            )
        )
        {
            ++nAdded;
            ++nRemoved;
            updated_ = true;
        }
    }
}


bool Foam::dcpRBFControlPoints::addNear
(
    const dcpRBFQualityRegion::rankedCell& cell
)
{
    const Eigen::RowVector3d x(cell[1], cell[2], cell[3]);
    if (set_.addNearest(x) < 0)
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


void Foam::dcpRBFControlPoints::endStep(const scalar minQuality)
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
    if (stepFrom_)
    {
        // this step's swaps were kept
        trialBackoff_ = settings_.selection().trialBackoff;
        stepFrom_.reset();
    }
    set_.nextStep();
    if (backedOff_)
    {
        trialQuality_ = minQuality;
        backedOff_ = false;
    }
    if (trialWait_ > 0)
    {
        --trialWait_;
    }
    if (blendFrom_ && ++blendStep_ >= settings_.selection().swapBlendSteps)
    {
        blendFrom_.reset();
    }
    if (time_.writeTime())
    {
        // refactorized from the indices, as a restart does (restarts are
        // exact); where a fresh factorization fails to round-off (a set
        // grown point by point past what it would take at once), the
        // incremental one is kept: the run goes on, a restart from here
        // meets the same refusal and says so
        try
        {
            if (updated_)
            {
                set_.refactorize();
                updated_ = false;
            }
            if (blendFrom_)
            {
                *blendFrom_ = set_.freshState(blendFrom_->indices, blendFrom_->ages);
            }
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
