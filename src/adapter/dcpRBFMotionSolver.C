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
    interpolant_(settings_.kernel(), settings_.polynomial(), projection_.dim())
{
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
    interpolant_(settings_.kernel(), settings_.polynomial(), projection_.dim())
{
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
    const scalar solveTime = timer.timeIncrement();

    // Interpolate at every point, keep the prescribed boundary values
    dcprbf::Values s(evalPoints_.rows(), 3);
    interpolant_.evaluate(evalPoints_.data(), evalPoints_.rows(), s.data());

    vectorField& disp = pointDisplacement_.primitiveFieldRef();
    boolList prescribed(mesh().nPoints(), false);
    const auto markPatches = [&](const labelList& patchIDs)
    {
        for (const label patchi : patchIDs)
        {
            for (const label pointi : mesh().boundaryMesh()[patchi].meshPoints())
            {
                prescribed[pointi] = true;
            }
        }
    };
    markPatches(settings_.movingPatchIDs());
    forAll(disp, pointi)
    {
        if (!prescribed[pointi])
        {
            disp[pointi] = projection_.fromCore(s.row(pointi).data());
        }
    }
    for (const label patchi : settings_.staticPatchIDs())
    {
        for (const label pointi : mesh().boundaryMesh()[patchi].meshPoints())
        {
            if (!prescribed[pointi]) disp[pointi] = Zero;
        }
    }
    pointDisplacement_.correctBoundaryConditions();

    const scalar evalTime = timer.timeIncrement();
    Info<< typeName << ": " << interpolant_.size() << " control points,"
        << " max boundary displacement " << d.rowwise().norm().maxCoeff()
        << ", solve " << solveTime << " s, evaluation " << evalTime << " s"
        << endl;
}


void Foam::dcpRBFMotionSolver::updateMesh(const mapPolyMesh&)
{
    FatalErrorInFunction
        << typeName << " does not support topology changes (mesh refinement,"
        << " layer addition, ...): the control points and reference points"
        << " would no longer match the mesh" << exit(FatalError);
}


// ************************************************************************* //
