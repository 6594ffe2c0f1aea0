/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFSwapRule.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dcpRBFSwapRule, 0);
    defineRunTimeSelectionTable(dcpRBFSwapRule, context);

    // the base: no swaps (selection all and greedy)
    addNamedToRunTimeSelectionTable(dcpRBFSwapRule, dcpRBFSwapRule, context, none);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFSwapRule::dcpRBFSwapRule
(
    const dcpRBFContext& context,
    dcpRBFControlPoints& controlPoints,
    dcpRBFQualityMeasurement& quality,
    dcpRBFInterpolation& interpolation
)
:
    context_(context),
    controlPoints_(controlPoints),
    quality_(quality),
    interpolation_(interpolation)
{}


// * * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::dcpRBFSwapRule> Foam::dcpRBFSwapRule::New
(
    const dcpRBFContext& context,
    dcpRBFControlPoints& controlPoints,
    dcpRBFQualityMeasurement& quality,
    dcpRBFInterpolation& interpolation
)
{
    // (the keyword's value was validated against the table's choices when
    // read: a name missing here is a rule not built into the library)
    const word name(context.settings().selection().swapRuleName());
    auto cstrIter = contextConstructorTablePtr_->cfind(name);
    if (!cstrIter.good())
    {
        FatalErrorInFunction
            << "Unknown swapRule " << name << nl << nl
            << "Valid swap rules: "
            << contextConstructorTablePtr_->sortedToc()
            << exit(FatalError);
    }
    return autoPtr<dcpRBFSwapRule>
    (
        cstrIter()(context, controlPoints, quality, interpolation)
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFSwapRule::lowestCells(const label) const
{
    return max(label(1), context_.settings().selection().nSwap);
}


// ************************************************************************* //
