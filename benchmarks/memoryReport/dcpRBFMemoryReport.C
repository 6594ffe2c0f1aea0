/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFMemoryReport.H"
#include "dcpRBFMotionSolver.H"
#include "dcpRBFResidentMemory.H"
#include "dynamicMotionSolverFvMesh.H"
#include "addToRunTimeSelectionTable.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(dcpRBFMemoryReport, 0);
    addToRunTimeSelectionTable
    (
        functionObject,
        dcpRBFMemoryReport,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::dcpRBFMemoryReport::dcpRBFMemoryReport
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    meshMB_(dcpRBFResidentMemory::residentMB()),
    reported_(std::size_t(-1))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::dcpRBFMemoryReport::execute()
{
    // (dynamic_cast: refCast's message is ambiguous between the mesh's
    // bases)
    const auto* moving = dynamic_cast<const dynamicMotionSolverFvMesh*>(&mesh_);
    if (!moving)
    {
        FatalErrorInFunction
            << "function object " << name() << " (" << typeName
            << ") needs dynamicFvMesh dynamicMotionSolverFvMesh"
            << exit(FatalError);
    }
    const auto* solver =
        dynamic_cast<const dcpRBFMotionSolver*>(&moving->motion());
    if (!solver)
    {
        FatalErrorInFunction
            << "function object " << name() << " (" << typeName
            << ") needs motionSolver dcpRBF, not " << moving->motion().type()
            << exit(FatalError);
    }
    const std::size_t points = solver->interpolation().storedBytes();
    const std::size_t candidates = solver->controlPoints().block().storedBytes();

    label changed = points + candidates != reported_;
    reduce(changed, maxOp<label>());
    if (!changed)
    {
        return true;
    }
    reported_ = points + candidates;
    const scalar MB = 1024*1024;
    scalar mesh = meshMB_;
    scalar atPoints = points/MB;
    scalar atCandidates = candidates/MB;
    reduce(mesh, maxOp<scalar>());
    reduce(atPoints, maxOp<scalar>());
    reduce(atCandidates, maxOp<scalar>());
    Info<< "dcpRBF: resident memory by part, largest processor [MB]:"
        << " mesh " << mesh << ", stored matrices " << atPoints
        << " (mesh points) " << atCandidates << " (candidates)" << endl;
    return true;
}


bool Foam::functionObjects::dcpRBFMemoryReport::write()
{
    return true;
}


// ************************************************************************* //
