/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
\*---------------------------------------------------------------------------*/

#include "dcpRBFMotionSolver.H"
#include "dcpRBFVersion.H"
#include "addToRunTimeSelectionTable.H"
#include "emptyPolyPatch.H"
#include "clockTime.H"
#include "OFstream.H"
#include "OSspecific.H"

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


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Moving boundary points (core coordinates)
dcprbf::Points movingPoints(const Foam::dcpRBFBoundaryPoints& b)
{
    Foam::label n = 0;
    for (const bool m : b.moving()) n += m;
    dcprbf::Points p(n, 3);
    n = 0;
    forAll(b.moving(), i)
    {
        if (b.moving()[i]) p.row(n++) = b.points().row(i);
    }
    return p;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFMotionSolver::warnUnlistedPatches() const
{
    const polyBoundaryMesh& patches = mesh().boundaryMesh();
    wordList unlisted;
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        if
        (
            !settings_.movingPatchIDs().found(patchi)
         && !settings_.staticPatchIDs().found(patchi)
         && !polyPatch::constraintType(pp.type())
        )
        {
            unlisted.append(pp.name());
        }
    }
    if (unlisted.size())
    {
        WarningInFunction
            << "Patches in neither movingPatches nor staticPatches: "
            << unlisted << nl
            << "    Their points move with the interpolated displacement"
            << " (constraint patches such as symmetryPlane apply their own"
            << " constraint and are not listed here)."
            << endl;
    }
}


void Foam::dcpRBFMotionSolver::setThreads() const
{
    #ifdef _OPENMP
    // MPI ranks x OpenMP threads beyond the cores slows everything down
    // several times: one thread per rank unless the user says otherwise
    if (Pstream::parRun() && getEnv("OMP_NUM_THREADS").empty())
    {
        omp_set_num_threads(1);
    }
    Info<< typeName << ": " << omp_get_max_threads() << " OpenMP thread(s)"
        << (Pstream::parRun() ? " per processor" : "")
        << " (set OMP_NUM_THREADS to change)" << endl;
    #endif
}


void Foam::dcpRBFMotionSolver::markBoundaryPoints()
{
    const polyBoundaryMesh& patches = mesh().boundaryMesh();
    for (const label patchi : settings_.staticPatchIDs())
    {
        for (const label pointi : patches[patchi].meshPoints())
        {
            onBoundary_[pointi] = true;
        }
    }
    for (const label patchi : settings_.movingPatchIDs())
    {
        for (const label pointi : patches[patchi].meshPoints())
        {
            onBoundary_[pointi] = true;
            prescribed_[pointi] = true;
        }
    }
}


Foam::scalar Foam::dcpRBFMotionSolver::interpolateDisplacement
(
    const dcprbf::Values& d
)
{
    const dcprbf::RbfEvaluator& s = controlPoints_.evaluator();
    dcprbf::Values v(evalPoints_.rows(), 3);
    s.evaluate(evalPoints_.data(), evalPoints_.rows(), v.data());

    vectorField& disp = pointDisplacement_.primitiveFieldRef();
    forAll(disp, pointi)
    {
        if (!prescribed_[pointi])
        {
            disp[pointi] =
                onBoundary_[pointi] ? Zero : projection_.fromCore(v.row(pointi).data());
        }
    }

    // Error at the boundary points, blended into the volume
    const dcprbf::Values error(d - s.evaluate(boundaryPoints_.points()));
    if (settings_.boundaryCorrection())
    {
        correction_.apply(error, onBoundary_, projection_, disp);
    }
    pointDisplacement_.correctBoundaryConditions();

    scalar err = 0;
    forAll(boundaryPoints_.moving(), i)
    {
        if (boundaryPoints_.moving()[i]) err = max(err, error.row(i).norm());
    }
    const scalar dMax = d.rows() ? d.rowwise().norm().maxCoeff() : 0;
    return dMax > 0 ? err/dMax : 0;
}


void Foam::dcpRBFMotionSolver::guardQuality
(
    const dcprbf::Values& d,
    dcpRBFStepLog::record& r
)
{
    const scalar floor = settings_.qualityFloor();
    const label nRanked = max(label(1), settings_.selection().nSwap);
    for (label iter = 0; ; ++iter)
    {
        lastPoints_ = points0() + pointDisplacement_.primitiveField();
        lastQuality_ = region_.measure(points0(), lastPoints_, nRanked);
        const dcpRBFQualityRegion::summary& q = lastQuality_;
        r.nMovedCells = q.nCells;
        r.minQuality = q.minQuality;
        r.meanQuality = q.meanQuality;

        if (q.minQuality >= floor || q.worst.empty())
        {
            break;
        }
        if (iter >= settings_.guardIterations() || !controlPoints_.addNear(q.worst[0]))
        {
            const word t(mesh().time().timeName());
            if (settings_.onFloorFailure() == dcpRBFSettings::floorAction::stop)
            {
                FatalErrorInFunction
                    << "Time " << t << ": minimum cell quality " << q.minQuality
                    << " below qualityFloor " << floor << " after " << iter
                    << " guard additions (" << q.nInverted << " inverted"
                    << " cells). Stopping (qualityFloorAction stop)."
                    << exit(FatalError);
            }
            WarningInFunction
                << "Time " << t << ": minimum cell quality " << q.minQuality
                << " below qualityFloor " << floor << " after " << iter
                << " guard additions; continuing (qualityFloorAction warn)"
                << endl;
            break;
        }
        ++r.nAdded;
        controlPoints_.solve(d);
        r.boundaryError = interpolateDisplacement(d);
    }

    if (lastQuality_.nInverted)
    {
        WarningInFunction
            << "Time " << mesh().time().timeName() << ": "
            << lastQuality_.nInverted << " inverted or degenerate cells"
            << " (quality <= 0, minimum " << r.minQuality << "). The mesh is"
            << " invalid: reduce the motion per step, enlarge supportRadius"
            << " or use selection dynamic with a qualityFloor." << endl;
    }
}


Foam::dcpRBFQualityRegion::summary Foam::dcpRBFMotionSolver::currentQuality()
{
    const pointField& p = mesh().points();
    bool same = lastPoints_.size() == p.size();
    for (label i = 0; same && i < p.size(); ++i)
    {
        same = (p[i] == lastPoints_[i]);
    }
    if (!returnReduce(same, andOp<bool>()))
    {
        lastQuality_ =
            region_.measure(points0(), p, max(label(1), settings_.selection().nSwap));
        lastPoints_ = p;
    }
    return lastQuality_;
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
    forAll(idx, k) os << "1 " << k << nl;
    os  << "POINT_DATA " << idx.size() << nl
        << "SCALARS moving int 1" << nl << "LOOKUP_TABLE default" << nl;
    for (const Eigen::Index i : idx) os << int(boundaryPoints_.moving()[i]) << nl;
    os  << "SCALARS age int 1" << nl << "LOOKUP_TABLE default" << nl;
    for (const int a : controlPoints_.set().ages()) os << a << nl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

#define dcpRBFMotionSolverMembers(points0Ref)                                  \
    settings_(coeffDict(), mesh),                                              \
    projection_(mesh),                                                         \
    boundaryPoints_                                                            \
    (                                                                          \
        mesh, projection_, settings_.movingPatchIDs(),                         \
        settings_.staticPatchIDs(), points0Ref                                 \
    ),                                                                         \
    evalPoints_(projection_.toCore(points0Ref)),                               \
    controlPoints_(mesh, settings_, boundaryPoints_, projection_.dim()),       \
    prescribed_(mesh.nPoints(), false),                                        \
    onBoundary_(mesh.nPoints(), false),                                        \
    region_                                                                    \
    (                                                                          \
        mesh, projection_, points0Ref, movingPoints(boundaryPoints_),          \
        settings_.kernel().radius(), settings_.metric()                        \
    ),                                                                         \
    correction_(evalPoints_, boundaryPoints_, settings_.kernel().radius()),    \
    log_(mesh.time())

Foam::dcpRBFMotionSolver::dcpRBFMotionSolver
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    displacementMotionSolver(mesh, dict, typeName),
    dcpRBFMotionSolverMembers(points0())
{
    setThreads();
    markBoundaryPoints();
    warnUnlistedPatches();
    Info<< typeName << ": " << boundaryPoints_.size() << " boundary points ("
        << word(settings_.kernel().name()) << ", supportRadius "
        << settings_.kernel().radius() << ", polynomial "
        << Switch(settings_.polynomial()) << ", " << projection_.dim()
        << "D, selection "
        << dcpRBFSelectionSettings::modeNames[label(settings_.selection().selection)]
        << "), " << region_.size() << " cells in reach" << endl;
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
    dcpRBFMotionSolverMembers(this->points0())
{
    setThreads();
    markBoundaryPoints();
    warnUnlistedPatches();
}

#undef dcpRBFMotionSolverMembers


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::pointField> Foam::dcpRBFMotionSolver::curPoints() const
{
    tmp<pointField> tcurPoints
    (
        points0() + pointDisplacement_.primitiveField()
    );
    twoDCorrectPoints(tcurPoints.ref());
    return tcurPoints;
}


void Foam::dcpRBFMotionSolver::solve()
{
    clockTime timer;
    dcpRBFStepLog::record r;

    // 1. Dynamic swaps from the quality of the mesh as it is
    if (controlPoints_.ready())
    {
        const dcpRBFQualityRegion::summary q(currentQuality());
        if (q.minQuality < 1 - 1e-12)
        {
            controlPoints_.swap(q, r.nAdded, r.nRemoved);
        }
    }

    // 2. This step's boundary displacement; (re)selection
    pointDisplacement_.boundaryFieldRef().updateCoeffs();
    pointDisplacement_.correctBoundaryConditions();
    const dcprbf::Values d
    (
        boundaryPoints_.gather(pointDisplacement_.primitiveField())
    );
    if (!controlPoints_.select(d))
    {
        // Nothing moves yet: interior points stay put
        vectorField& disp = pointDisplacement_.primitiveFieldRef();
        forAll(disp, pointi)
        {
            if (!prescribed_[pointi]) disp[pointi] = Zero;
        }
        pointDisplacement_.correctBoundaryConditions();
        log_.write(r);
        return;
    }
    controlPoints_.solve(d);
    r.nAdded += controlPoints_.reselect(d);
    r.selectTime = timer.timeIncrement();

    // 3. Interpolate, snap the boundary, 4. guard the quality
    r.boundaryError = interpolateDisplacement(d);
    r.solveTime = timer.timeIncrement();
    guardQuality(d, r);
    r.evalTime = timer.timeIncrement();

    r.nControl = controlPoints_.size();
    controlPoints_.endStep();
    if (mesh().time().writeTime())
    {
        writeControlPoints(d);
    }
    log_.write(r);
}


void Foam::dcpRBFMotionSolver::updateMesh(const mapPolyMesh&)
{
    FatalErrorInFunction
        << typeName << " does not support topology changes (mesh refinement,"
        << " layer addition, ...): the control points and reference points"
        << " would no longer match the mesh" << exit(FatalError);
}


// ************************************************************************* //
