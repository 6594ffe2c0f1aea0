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
    the component one where one component drives it
    (dcpRBFComponentMotionSolver::drives()), else dcpRBFMotionSolver.
\*---------------------------------------------------------------------------*/

#include "dcpRBFVelocityMotionSolver.H"
#include "dcpRBFComponentMotionSolver.H"
#include "valuePointPatchField.H"
#include "pointFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dcpRBFVelocityMotionSolver, 0);
}

namespace
{
    using namespace Foam;

    //- motionSolver dcpRBF: the velocity-driven, component or displacement
    //  solver, as the case is (the only name in the motionSolver table: the
    //  driven solvers are not selected by their own)
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
            if (dcpRBFComponentMotionSolver::drives(mesh, dict))
            {
                return autoPtr<motionSolver>
                (
                    new dcpRBFComponentMotionSolver(mesh, dict)
                );
            }
            return autoPtr<motionSolver>(new dcpRBFMotionSolver(mesh, dict));
        }

    public:

        dcpRBFMotionSolverSelector()
        {
            motionSolver::constructdictionaryConstructorTables();
            // (the name's literal: the word typeName of another file may
            // not be made yet when this file's statics are)
            motionSolver::dictionaryConstructorTablePtr_->set
            (
                dcpRBFMotionSolver::typeName_(), New
            );
        }

        ~dcpRBFMotionSolverSelector()
        {
            if (motionSolver::dictionaryConstructorTablePtr_)
            {
                motionSolver::dictionaryConstructorTablePtr_->erase
                (
                    dcpRBFMotionSolver::typeName_()
                );
            }
        }
    };

    const dcpRBFMotionSolverSelector selectDcpRBF_;
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
    return
        !dcpRBFMotionSolver::inTime<vector>(mesh, "pointDisplacement")
     && dcpRBFMotionSolver::inTime<vector>(mesh, "pointMotionU");
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFVelocityMotionSolver::dcpRBFVelocityMotionSolver
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    dcpRBFDrivenMotionSolver<velocityMotionSolver>(mesh, dict)
{
    drive(dcpRBFSettings::conditionsOf(pointMotionU_, true));
    Info<< dcpRBFMotionSolver::typeName << ": velocity-driven (pointMotionU"
        << (
               found("dynamicFvMesh")
             ? ", dynamicFvMesh " + get<word>("dynamicFvMesh") : string()
           ).c_str()
        << "): the points of the patches whose velocity condition fixes the"
        << " value move by deltaT times it each step, as velocityLaplacian"
        << " moves them; the rest is interpolated" << endl;
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
    const pointField& points0 = driven_->points0();
    forAll(velocity, patchi)
    {
        if (driven_->fixes(patchi))
        {
            const labelList& meshPoints = velocity[patchi].patch().meshPoints();
            const vectorField& u =
                refCast<const valuePointPatchField<vector>>(velocity[patchi]);
            driven_->prescribe
            (
                patchi,
                vectorField(points, meshPoints)
              - vectorField(points0, meshPoints) + deltaT*u
            );
        }
    }
}


void Foam::dcpRBFVelocityMotionSolver::update(const pointField& newPoints)
{
    // the mesh's velocity, as a velocity solver leaves it (the conditions
    // evaluated: ready for the next step's)
    pointMotionU_.primitiveFieldRef() =
        (newPoints - mesh().points())/mesh().time().deltaTValue();
    pointMotionU_.correctBoundaryConditions();
}


// ************************************************************************* //
