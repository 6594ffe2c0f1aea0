/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFErrorGuidedSwaps.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dcpRBFErrorGuidedSwaps, 0);
    addNamedToRunTimeSelectionTable
    (
        dcpRBFSwapRule, dcpRBFErrorGuidedSwaps, components, errorGuided
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFErrorGuidedSwaps::dcpRBFErrorGuidedSwaps
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
    ),
    pointCount_(mesh)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dcpRBFErrorGuidedSwaps::measuresFirst() const
{
    // trials due, not a rescue (the last step's mesh had no inverted cell),
    // and the last step's measurement to pick the window from
    return !
    (
        controlPoints_.canTrial(false)
     && quality_.last().nCells > 0
     && quality_.last().nInverted == 0
     && !quality_.last().worst.empty()
     && quality_.last().minQuality < 1 - 1e-12
    );
}


void Foam::dcpRBFErrorGuidedSwaps::afterInterpolate
(
    const dcprbf::Values& d,
    dcpRBFStepState& step,
    const bool measured
)
{
    // waiting after undone trials unless the mesh got worse since
    dcpRBFTrialSchedule& schedule = controlPoints_.trialSchedule();
    const bool waitEnded =
        measured && schedule.endWaitIfWorse(quality_.last().minQuality);
    const FixedList<label, 2> before(schedule.save());
    if
    (
        trySwaps(d, step, measured) == 0
     && !measured
     && quality_.last().nInverted > 0
    )
    {
        // the mesh without swaps (measured) has inverted cells: the
        // rescue, backing off as if the trials had not been made
        schedule.restore(before);
        trySwaps(d, step, true);
    }
    step.waitEnded = waitEnded;
}


Foam::label Foam::dcpRBFErrorGuidedSwaps::lowestCells(const label nCells) const
{
    const label k = dcpRBFSwapRule::lowestCells(nCells);
    return
        settings_.selection().selection == dcpRBFSelectionSettings::mode::dynamic
      ? max(k, max(minTrialWindow, label(trialWindowFraction*nCells)) + 1)
      : k;
}


Foam::scalar Foam::dcpRBFErrorGuidedSwaps::interpolate(const dcprbf::Values& d)
{
    quality_.changed();
    return interpolation_.interpolate(d);
}


bool Foam::dcpRBFErrorGuidedSwaps::beatsUnswapped
(
    const vectorField& noSwapField,
    const scalar noSwapError,
    dcpRBFStepState& step
)
{
    // the swapped mesh aside, the mesh without swaps measured in its place
    vectorField& disp = pointDisplacement_.primitiveFieldRef();
    vectorField swappedField(disp);
    dcpRBFQualityRegion::summary swapped(std::move(quality_.last()));
    pointField swappedPoints(std::move(quality_.lastPoints()));
    const scalar swappedError = step.boundaryError;
    disp = noSwapField;
    step.boundaryError = noSwapError;
    quality_.measure();
    // (without swaps inverted: abandoned, the rescue follows, as it would
    // have had that mesh been measured first)
    if (quality_.last().nInverted == 0 && swapped.minQuality > quality_.last().minQuality)
    {
        disp.transfer(swappedField);
        quality_.last() = std::move(swapped);
        quality_.lastPoints().transfer(swappedPoints);
        quality_.setMeasured(true);
        step.boundaryError = swappedError;
        return true;
    }
    return false;
}


// ************************************************************************* //
