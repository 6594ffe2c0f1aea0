/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFVelocityMotionSolver, and motionSolver dcpRBF's selection: the
    velocity-driven solver where the case is velocity-driven (drives()),
    else dcpRBFMotionSolver.
\*---------------------------------------------------------------------------*/

#include "dcpRBFVelocityMotionSolver.H"
#include "addToRunTimeSelectionTable.H"
#include "fixedValuePointPatchFields.H"
#include "valuePointPatchField.H"
#include "pointFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dcpRBFVelocityMotionSolver, 0);

    addToRunTimeSelectionTable
    (
        motionSolver,
        dcpRBFVelocityMotionSolver,
        dictionary
    );

    //- motionSolver dcpRBF: the velocity-driven solver or the displacement
    //  one, as the case is
    class dcpRBFMotionSolverSelector
    {
        static autoPtr<motionSolver> New
        (
            const polyMesh& mesh,
            const IOdictionary& dict
        )
        {
            if (dcpRBFVelocityMotionSolver::drives(mesh, dict))
            {
                return autoPtr<motionSolver>
                (
                    new dcpRBFVelocityMotionSolver(mesh, dict)
                );
            }
            return autoPtr<motionSolver>(new dcpRBFMotionSolver(mesh, dict));
        }

    public:

        dcpRBFMotionSolverSelector()
        {
            motionSolver::constructdictionaryConstructorTables();
            motionSolver::dictionaryConstructorTablePtr_->set
            (
                dcpRBFMotionSolver::typeName, New
            );
        }

        ~dcpRBFMotionSolverSelector()
        {
            if (motionSolver::dictionaryConstructorTablePtr_)
            {
                motionSolver::dictionaryConstructorTablePtr_->erase
                (
                    dcpRBFMotionSolver::typeName
                );
            }
        }
    };

    static const dcpRBFMotionSolverSelector selectDcpRBF_;
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

bool Foam::dcpRBFVelocityMotionSolver::drives
(
    const polyMesh& mesh,
    const dictionary& dict
)
{
    if
    (
        dict.getOrDefault<word>("dynamicFvMesh", word::null)
     == "interfaceTrackingFvMesh"
    )
    {
        return true;
    }
    const auto has = [&mesh](const word& name)
    {
        return IOobject
        (
            name, mesh.time().timeName(), mesh, IOobject::MUST_READ
        ).typeHeaderOk<pointVectorField>(false);
    };
    return !has("pointDisplacement") && has("pointMotionU");
}


Foam::pointVectorField Foam::dcpRBFVelocityMotionSolver::displacementField
(
    const pointVectorField& pointMotionU,
    const pointField& points0
)
{
    const pointVectorField::Boundary& conditions = pointMotionU.boundaryField();
    wordList types(conditions.types());
    forAll(conditions, patchi)
    {
        if (conditions[patchi].fixesValue())
        {
            types[patchi] = fixedValuePointPatchVectorField::typeName;
        }
    }
    const polyMesh& mesh = pointMotionU.mesh().mesh();
    pointVectorField d
    (
        IOobject
        (
            "pointDisplacement",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false           // the displacement solver's copy registered
        ),
        pointMotionU.mesh(),
        dimensionedVector(dimLength, Zero),
        types
    );
    // the displacement of the points as they are (a restart: the written
    // time's), as a displacement case reads it from its time
    d.primitiveFieldRef() = mesh.points() - points0;
    forAll(conditions, patchi)
    {
        if (conditions[patchi].fixesValue())
        {
            d.boundaryFieldRef()[patchi] ==
                vectorField
                (
                    d.primitiveField(), conditions[patchi].patch().meshPoints()
                );
        }
    }
    return d;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFVelocityMotionSolver::dcpRBFVelocityMotionSolver
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    velocityMotionSolver(mesh, dict, dcpRBFMotionSolver::typeName)
{
    const pointIOField points0(points0MotionSolver::points0IO(mesh));
    Info<< dcpRBFMotionSolver::typeName << ": velocity-driven (pointMotionU"
        << (
               found("dynamicFvMesh")
             ? ", dynamicFvMesh " + get<word>("dynamicFvMesh") : string()
           ).c_str()
        << "): the points of the patches whose velocity condition fixes the"
        << " value move by deltaT times it each step, as velocityLaplacian"
        << " moves them; the rest is interpolated" << endl;
    displacement_.reset
    (
        new dcpRBFMotionSolver
        (
            mesh, *this, displacementField(pointMotionU_, points0), points0
        )
    );
    // registered once the patches' roles are inferred (from the velocity):
    // what cellDisplacement's conditions read; not written
    displacement_->pointDisplacement().checkIn();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFVelocityMotionSolver::prescribe()
{
    // the velocity's conditions once (oscillatingVelocity, ...; values a
    // mesh class has set stay)
    pointVectorField::Boundary& velocity = pointMotionU_.boundaryFieldRef();
    velocity.updateCoeffs();
    const scalar deltaT = mesh().time().deltaTValue();
    const pointField& points = mesh().points();
    const pointField& points0 = displacement_->points0();
    pointVectorField::Boundary& d =
        displacement_->pointDisplacement().boundaryFieldRef();
    forAll(velocity, patchi)
    {
        if (velocity[patchi].fixesValue())
        {
            const labelList& meshPoints = velocity[patchi].patch().meshPoints();
            const vectorField& u =
                refCast<const valuePointPatchField<vector>>(velocity[patchi]);
            d[patchi] ==
                vectorField(points, meshPoints) - vectorField(points0, meshPoints)
              + deltaT*u;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::pointField> Foam::dcpRBFVelocityMotionSolver::curPoints() const
{
    return displacement_->curPoints();
}


void Foam::dcpRBFVelocityMotionSolver::solve()
{
    prescribe();
    displacement_->solve();
    // the mesh's velocity, as a velocity solver leaves it (the conditions
    // evaluated: ready for the next step's)
    pointMotionU_.primitiveFieldRef() =
        (curPoints() - mesh().points())/mesh().time().deltaTValue();
    pointMotionU_.correctBoundaryConditions();
}


Foam::tmp<Foam::pointField> Foam::dcpRBFVelocityMotionSolver::newPoints()
{
    prescribe();
    tmp<pointField> tpoints(displacement_->newPoints());
    pointMotionU_.primitiveFieldRef() =
        (tpoints() - mesh().points())/mesh().time().deltaTValue();
    pointMotionU_.correctBoundaryConditions();
    return tpoints;
}


void Foam::dcpRBFVelocityMotionSolver::movePoints(const pointField& p)
{
    displacement_->movePoints(p);
}


void Foam::dcpRBFVelocityMotionSolver::updateMesh(const mapPolyMesh& map)
{
    displacement_->updateMesh(map);
}


bool Foam::dcpRBFVelocityMotionSolver::read()
{
    return velocityMotionSolver::read() && displacement_->read();
}


// ************************************************************************* //
