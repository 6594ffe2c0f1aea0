/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFDrivenDisplacement.H"
#include "fixedValuePointPatchFields.H"
#include "zeroGradientPointPatchFields.H"
#include "pointFields.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::pointVectorField Foam::dcpRBFDrivenDisplacement::displacementField
(
    const pointMesh& pMesh,
    const wordList& types,
    const boolList& fixes,
    const pointField& points0
)
{
    const polyMesh& mesh = pMesh.mesh();
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    wordList vectorTypes(types);
    forAll(vectorTypes, patchi)
    {
        if (fixes[patchi])
        {
            vectorTypes[patchi] = fixedValuePointPatchVectorField::typeName;
        }
        else if
        (
            patches[patchi].coupled()
         || polyPatch::constraintType(patches[patchi].type())
        )
        {
            vectorTypes[patchi] = patches[patchi].type();
        }
        else if
        (
            !pointPatchVectorField::pointPatchConstructorTablePtr_->found
            (
                vectorTypes[patchi]
            )
        )
        {
            // a scalar's condition without a vector kind: free, as a
            // component solver leaves it
            vectorTypes[patchi] = zeroGradientPointPatchVectorField::typeName;
        }
    }
    pointVectorField d
    (
        IOobject
        (
            "pointDisplacement",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false           // the solver's copy registered once it is made
        ),
        pMesh,
        dimensionedVector(dimLength, Zero),
        vectorTypes
    );
    // the points' displacement as they are, as a displacement case reads
    // it from its time
    d.primitiveFieldRef() = mesh.points() - points0;
    forAll(fixes, patchi)
    {
        if (fixes[patchi])
        {
            d.boundaryFieldRef()[patchi] ==
                vectorField(d.primitiveField(), patches[patchi].meshPoints());
        }
    }
    return d;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFDrivenDisplacement::dcpRBFDrivenDisplacement
(
    const polyMesh& mesh,
    const IOdictionary& dict,
    const wordList& types,
    const boolList& fixes
)
:
    fixes_(fixes)
{
    const pointIOField points0(points0MotionSolver::points0IO(mesh));
    solver_.reset
    (
        new dcpRBFMotionSolver
        (
            mesh, dict,
            displacementField(pointMesh::New(mesh), types, fixes, points0),
            points0
        )
    );
    // registered once the patches' roles are inferred (from the driving
    // field): what cellDisplacement's conditions read; not written
    solver_->pointDisplacement().checkIn();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFDrivenDisplacement::prescribe
(
    const label patchi,
    const vectorField& d
)
{
    solver_->pointDisplacement().boundaryFieldRef()[patchi] == d;
}


// ************************************************************************* //
