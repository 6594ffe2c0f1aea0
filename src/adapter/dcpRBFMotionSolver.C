/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
\*---------------------------------------------------------------------------*/

#include "dcpRBFMotionSolver.H"
#include "dcpRBFVersion.H"
#include "addToRunTimeSelectionTable.H"
#include "emptyPolyPatch.H"
#include "clockTime.H"

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
         && !isA<emptyPolyPatch>(pp)
         && !pp.coupled()
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
            << "    Their points move with the interpolated displacement."
            << endl;
    }
}


void Foam::dcpRBFMotionSolver::setControlPoints()
{
    try
    {
        interpolant_.setCentres(boundaryPoints_.points());
    }
    catch (const dcprbf::Error& e)
    {
        FatalIOErrorInFunction(coeffDict())
            << "Cannot build the RBF system on the "
            << boundaryPoints_.size() << " control points of movingPatches"
            << " and staticPatches: " << e.what() << exit(FatalIOError);
    }
    Info<< typeName << ": " << interpolant_.size() << " control points ("
        << word(settings_.kernel().name()) << ", supportRadius "
        << settings_.kernel().radius() << ", polynomial "
        << Switch(settings_.polynomial()) << ", " << projection_.dim()
        << "D)" << endl;
}


void Foam::dcpRBFMotionSolver::markPrescribedPoints()
{
    for (const label patchi : settings_.movingPatchIDs())
    {
        for (const label pointi : mesh().boundaryMesh()[patchi].meshPoints())
        {
            prescribed_[pointi] = true;
        }
    }
}


void Foam::dcpRBFMotionSolver::interpolateDisplacement()
{
    dcprbf::Values s(evalPoints_.rows(), 3);
    interpolant_.evaluate(evalPoints_.data(), evalPoints_.rows(), s.data());

    vectorField& disp = pointDisplacement_.primitiveFieldRef();
    forAll(disp, pointi)
    {
        if (!prescribed_[pointi])
        {
            disp[pointi] = projection_.fromCore(s.row(pointi).data());
        }
    }
    for (const label patchi : settings_.staticPatchIDs())
    {
        for (const label pointi : mesh().boundaryMesh()[patchi].meshPoints())
        {
            if (!prescribed_[pointi]) disp[pointi] = Zero;
        }
    }
    pointDisplacement_.correctBoundaryConditions();
}


Foam::scalar Foam::dcpRBFMotionSolver::boundaryError
(
    const dcprbf::Values& d
) const
{
    const dcprbf::Values s(interpolant_.evaluate(boundaryPoints_.points()));
    scalar err = 0;
    forAll(boundaryPoints_.moving(), i)
    {
        if (boundaryPoints_.moving()[i])
        {
            err = max(err, (s.row(i) - d.row(i)).norm());
        }
    }
    const scalar dMax = d.rows() ? d.rowwise().norm().maxCoeff() : 0;
    return dMax > 0 ? err/dMax : 0;
}


void Foam::dcpRBFMotionSolver::measureQuality(dcpRBFStepLog::record& r) const
{
    const vectorField& disp = pointDisplacement_.primitiveField();
    const pointField p(points0() + disp);
    const scalar tol = 1e-12*mesh().bounds().mag();
    const labelList cells(quality_.movedCells(disp, tol));
    const scalarField q(quality_.compute(cells, points0(), p));

    r.nMovedCells = returnReduce(cells.size(), sumOp<label>());
    r.minQuality = r.nMovedCells ? gMin(q) : 1;
    r.meanQuality = r.nMovedCells ? gSum(q)/r.nMovedCells : 1;
    const label nInverted = returnReduce(label(std::count_if(q.begin(), q.end(), [](scalar x) { return x <= 0; })), sumOp<label>());
    if (nInverted)
    {
        WarningInFunction
            << "Time " << mesh().time().timeName() << ": " << nInverted
            << " inverted or degenerate cells (quality <= 0, minimum "
            << r.minQuality << "). The mesh is invalid: reduce the motion"
            << " per step or enlarge supportRadius." << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFMotionSolver::dcpRBFMotionSolver
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    displacementMotionSolver(mesh, dict, typeName),
    settings_(coeffDict(), mesh),
    projection_(mesh),
    boundaryPoints_
    (
        mesh,
        projection_,
        settings_.movingPatchIDs(),
        settings_.staticPatchIDs(),
        points0()
    ),
    evalPoints_(projection_.toCore(points0())),
    interpolant_(settings_.kernel(), settings_.polynomial(), projection_.dim()),
    prescribed_(mesh.nPoints(), false),
    quality_(mesh),
    log_(mesh.time())
{
    markPrescribedPoints();
    warnUnlistedPatches();
    setControlPoints();
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
    settings_(coeffDict(), mesh),
    projection_(mesh),
    boundaryPoints_
    (
        mesh,
        projection_,
        settings_.movingPatchIDs(),
        settings_.staticPatchIDs(),
        this->points0()
    ),
    evalPoints_(projection_.toCore(this->points0())),
    interpolant_(settings_.kernel(), settings_.polynomial(), projection_.dim()),
    prescribed_(mesh.nPoints(), false),
    quality_(mesh),
    log_(mesh.time())
{
    markPrescribedPoints();
    warnUnlistedPatches();
    setControlPoints();
}


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

    // Boundary conditions: prescribed displacement into the point field
    pointDisplacement_.boundaryFieldRef().updateCoeffs();
    pointDisplacement_.correctBoundaryConditions();

    const dcprbf::Values d
    (
        boundaryPoints_.gather(pointDisplacement_.primitiveField())
    );
    try
    {
        interpolant_.solve(d);
    }
    catch (const dcprbf::Error& e)
    {
        FatalErrorInFunction
            << "RBF solve failed: " << e.what() << exit(FatalError);
    }
    r.solveTime = timer.timeIncrement();

    interpolateDisplacement();
    r.evalTime = timer.timeIncrement();

    r.nControl = interpolant_.size();
    r.boundaryError = boundaryError(d);
    measureQuality(r);
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
