/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFCellDisplacement.H"
#include "cellMotionFvPatchFields.H"
#include "fvMesh.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::wordList Foam::dcpRBFCellDisplacement::boundaryTypes() const
{
    // (a constraint patch's own type, not its point condition's: that may
    // be a point condition alone, solidBodyMotionDisplacement on an overset
    // patch say, which no finite-volume field has)
    const polyBoundaryMesh& patches = pointDisplacement_.mesh().mesh().boundaryMesh();
    wordList types(patches.size(), cellMotionFvPatchVectorField::typeName);
    forAll(patches, patchi)
    {
        if (polyPatch::constraintType(patches[patchi].type()))
        {
            types[patchi] = patches[patchi].type();
        }
    }
    return types;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFCellDisplacement::dcpRBFCellDisplacement
(
    const pointVectorField& pointDisplacement
)
:
    pointDisplacement_(pointDisplacement)
{
    const polyMesh& mesh = pointDisplacement.mesh().mesh();
    const fvMesh* fv = isA<fvMesh>(mesh);
    if (!fv)
    {
        return;
    }
    field_.reset
    (
        new volVectorField
        (
            IOobject
            (
                "cellDisplacement",
                mesh.time().timeName(),
                mesh,
                IOobject::READ_IF_PRESENT,
                IOobject::AUTO_WRITE
            ),
            *fv,
            dimensionedVector(pointDisplacement.dimensions(), Zero),
            boundaryTypes()
        )
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFCellDisplacement::update()
{
    if (!field_.valid())
    {
        return;
    }
    const vectorField& d = pointDisplacement_.primitiveField();
    const labelListList& cellPoints = field_->mesh().cellPoints();
    vectorField& cells = field_->primitiveFieldRef();
    forAll(cells, celli)
    {
        vector sum(Zero);
        for (const label pointi : cellPoints[celli])
        {
            sum += d[pointi];
        }
        cells[celli] = sum/scalar(cellPoints[celli].size());
    }
    field_->correctBoundaryConditions();
}


// ************************************************************************* //
