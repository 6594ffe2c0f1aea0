/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFNoSwaps.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dcpRBFNoSwaps, 0);
    addNamedToRunTimeSelectionTable(dcpRBFSwapRule, dcpRBFNoSwaps, context, none);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFNoSwaps::dcpRBFNoSwaps
(
    const dcpRBFContext& context,
    dcpRBFControlPoints& controlPoints,
    dcpRBFQualityMeasurement& quality,
    dcpRBFInterpolation& interpolation
)
:
    dcpRBFSwapRule(context, controlPoints, quality, interpolation)
{}


// ************************************************************************* //
