/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFFvMesh.H"
#include "dcpRBFDictReader.H"
#include "dcpRBFSettings.H"
#include "points0MotionSolver.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dcpRBFFvMesh, 0);
    addToRunTimeSelectionTable(dynamicFvMesh, dcpRBFFvMesh, IOobject);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

dcprbf::TetQuality::Metric readMetric(const Foam::dictionary& dict)
{
    const Foam::dictionary* coeffs = dict.findDict("dcpRBFFvMeshCoeffs");
    const Foam::dcpRBFDictReader r(coeffs ? *coeffs : Foam::dictionary::null);
    r.checkKeywordsOf("dcpRBFFvMeshCoeffs");
    return r.getEnum
    (
        Foam::dcpRBFKeywords::get("dcpRBFFvMeshCoeffs", "qualityMetric"),
        Foam::dcpRBFSettings::metricNames
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::pointField& Foam::dcpRBFFvMesh::referencePoints() const
{
    if (isA<points0MotionSolver>(motion()))
    {
        return refCast<const points0MotionSolver>(motion()).points0();
    }
    return initialPoints_;
}


void Foam::dcpRBFFvMesh::updateQuality()
{
    cellQuality_.primitiveFieldRef() = quality_.compute(points());
    cellQuality_.correctBoundaryConditions();

    const scalarField& q = cellQuality_.primitiveField();
    label nInverted = 0;
    for (const scalar x : q) nInverted += (x <= 0);
    reduce(nInverted, sumOp<label>());
    Info<< typeName << ": cell quality min " << gMin(q) << " mean "
        << gAverage(q) << ", " << nInverted << " inverted cells" << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFFvMesh::dcpRBFFvMesh(const IOobject& io)
:
    dynamicMotionSolverFvMesh(io),
    initialPoints_(points()),
    quality_(*this, identity(nCells()), referencePoints(), readMetric(motion())),
    cellQuality_
    (
        IOobject
        (
            "cellQuality",
            time().timeName(),
            *this,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        *this,
        dimensionedScalar("one", dimless, 1.0)
    )
{
    updateQuality();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dcpRBFFvMesh::update()
{
    const bool changed = dynamicMotionSolverFvMesh::update();
    updateQuality();
    return changed;
}


// ************************************************************************* //
