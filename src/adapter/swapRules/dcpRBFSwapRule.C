/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFSwapRule.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dcpRBFSwapRule, 0);
    defineRunTimeSelectionTable(dcpRBFSwapRule, components);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFSwapRule::dcpRBFSwapRule
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
    mesh_(mesh),
    settings_(settings),
    controlPoints_(controlPoints),
    region_(region),
    quality_(quality),
    interpolation_(interpolation),
    pointDisplacement_(pointDisplacement),
    points0_(points0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFSwapRule::lowestCells(const label) const
{
    // outside selection dynamic no rule swaps: the guard's worst cell
    return max(label(1), settings_.selection().nSwap);
}


// * * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::dcpRBFSwapRule> Foam::dcpRBFSwapRule::New
(
    const word& ruleName,
    const polyMesh& mesh,
    const dcpRBFSettings& settings,
    dcpRBFControlPoints& controlPoints,
    const dcpRBFQualityRegion& region,
    dcpRBFQualityMeasurement& quality,
    dcpRBFInterpolation& interpolation,
    pointVectorField& pointDisplacement,
    const pointField& points0
)
{
    // (the keyword's value was validated against the rule names when read)
    auto cstrIter = componentsConstructorTablePtr_->cfind(ruleName);
    if (!cstrIter.good())
    {
        FatalErrorInFunction
            << "Unknown swapRule " << ruleName << nl << nl
            << "Valid swap rules: "
            << componentsConstructorTablePtr_->sortedToc()
            << exit(FatalError);
    }
    return autoPtr<dcpRBFSwapRule>
    (
        cstrIter()
        (
            mesh, settings, controlPoints, region, quality, interpolation,
            pointDisplacement, points0
        )
    );
}


// ************************************************************************* //
