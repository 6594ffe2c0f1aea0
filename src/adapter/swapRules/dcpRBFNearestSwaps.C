/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFNearestSwaps.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dcpRBFNearestSwaps, 0);
    addNamedToRunTimeSelectionTable
    (
        dcpRBFSwapRule, dcpRBFNearestSwaps, components, nearest
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFNearestSwaps::dcpRBFNearestSwaps
(
    const polyMesh& mesh,
    const dcpRBFSettings& settings,
    dcpRBFControlPoints& controlPoints,
    const dcpRBFQualityRegion& region,
    dcpRBFQualityMeasurement& quality,
    dcpRBFInterpolation& interpolation,
    pointVectorField& pointDisplacement,
    const pointField& points0
)
:
    dcpRBFSwapRule
    (
        mesh, settings, controlPoints, region, quality, interpolation,
        pointDisplacement, points0
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFNearestSwaps::lowestCells(const label nCells) const
{
    return
        settings_.selection().selection == dcpRBFSelectionSettings::mode::dynamic
      ? -1 : dcpRBFSwapRule::lowestCells(nCells);
}


bool Foam::dcpRBFNearestSwaps::readsBestCells() const
{
    return
        settings_.selection().selection == dcpRBFSelectionSettings::mode::dynamic;
}


void Foam::dcpRBFNearestSwaps::beforeSolve(dcpRBFStepState& step)
{
    if (controlPoints_.ready() && controlPoints_.swapsBeforeSolve())
    {
        const dcpRBFQualityRegion::summary& q = quality_.current();
        if (q.minQuality < 1 - 1e-12)
        {
            controlPoints_.swap(q, step.nAdded, step.nRemoved);
        }
    }
}


// ************************************************************************* //
