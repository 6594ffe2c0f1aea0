/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
\*---------------------------------------------------------------------------*/

#include "dcpRBFControlPoints.H"
#include "GreedySelector.hpp"
#include "Time.H"

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
    // The greedy's factorization is taken over (same candidates, frame and
    // kernel): no O(N^3) refactorization
    set_.reset(r.selected, std::move(*r.factorization));
    updated_ = true;
}


void Foam::dcpRBFControlPoints::storeState()
{
    labelList indices(set_.indices().begin(), set_.indices().end());
    labelList ages(set_.ages().begin(), set_.ages().end());
    state_.set("ready", ready_);
    state_.set("indices", indices);
    state_.set("ages", ages);
}


bool Foam::dcpRBFControlPoints::readState()
{
    if (!state_.found("indices") || !state_.get<bool>("ready"))
    {
        return false;
    }
    const labelList indices(state_.get<labelList>("indices"));
    const labelList ages(state_.get<labelList>("ages"));
    for (const label i : indices)
    {
        if (i < 0 || i >= boundary_.size())
        {
            FatalIOErrorInFunction(state_)
                << "Control point index " << i << " out of range [0, "
                << boundary_.size() << "): the state does not match this mesh"
                << " and dcpRBFCoeffs" << exit(FatalIOError);
        }
    }
    set_.reset(std::vector<Eigen::Index>(indices.begin(), indices.end()));
    set_.setAges(std::vector<int>(ages.begin(), ages.end()));
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
    state_
    (
        IOobject
        (
            "dcpRBFState",
            mesh.time().timeName(),
            "uniform",
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        )
    )
{
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
            << e.what() << exit(FatalError);
    }
    storeState();
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
            << "    The candidates are the points of movingPatches and"
            << " staticPatches. With the polynomial they must span the space"
            << " (not all on one line in 2D, not all in one plane in 3D): add"
            << " a patch off that plane to staticPatches, or set polynomial"
            << " false" << exit(FatalError);
    }
    ready_ = true;
    return true;
}


void Foam::dcpRBFControlPoints::solve(const dcprbf::Values& d)
{
    try
    {
        set_.solve(d);
    }
    catch (const dcprbf::Error& e)
    {
        FatalErrorInFunction
            << "RBF solve failed: " << e.what() << exit(FatalError);
    }
}


Foam::scalar Foam::dcpRBFControlPoints::boundaryError
(
    const dcprbf::Values& d,
    label& worst
) const
{
    const dcprbf::Values s(set_.evaluator().evaluate(boundary_.points()));
    scalar err = 0;
    worst = -1;
    forAll(boundary_.moving(), i)
    {
        const scalar e = (s.row(i) - d.row(i)).norm();
        if (boundary_.moving()[i] && e > err)
        {
            err = e;
            worst = i;
        }
    }
    const scalar dMax = d.rows() ? d.rowwise().norm().maxCoeff() : 0;
    return dMax > 0 ? err/dMax : 0;
}


bool Foam::dcpRBFControlPoints::swapping() const
{
    return settings_.selection().selection == dcpRBFSelectionSettings::mode::dynamic;
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
    if (settings_.selection().selection != dcpRBFSelectionSettings::mode::dynamic)
    {
        return;
    }
    const label n = settings_.selection().nSwap;
    for (label k = 0; k < min(n, q.worst.size()); ++k)
    {
        if (addNear(q.worst[k])) ++nAdded;
    }
    for (label k = 0; k < min(n, q.best.size()); ++k)
    {
        const Eigen::RowVector3d x(q.best[k][1], q.best[k][2], q.best[k][3]);
        if (set_.removeNearest(x) >= 0)
        {
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


void Foam::dcpRBFControlPoints::endStep()
{
    set_.nextStep();
    if (updated_ && time_.writeTime())
    {
        set_.refactorize();
        updated_ = false;
    }
    storeState();
}


// ************************************************************************* //
