/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFErrorGuidedSwaps.H"
#include "dcpRBFDictReader.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dcpRBFErrorGuidedSwaps, 0);
    addNamedToRunTimeSelectionTable
    (
        dcpRBFSwapRule, dcpRBFErrorGuidedSwaps, context, errorGuided
    );

    defineTypeNameAndDebug(dcpRBFErrorGuidedSettings, 0);
    addToRunTimeSelectionTable
    (
        dcpRBFSwapRuleSettings, dcpRBFErrorGuidedSettings, dictionary
    );
}

const Foam::Enum<Foam::dcpRBFErrorGuidedSettings::trialPoints>
Foam::dcpRBFErrorGuidedSettings::trialPointsNames
({
    {trialPoints::window, "window"},
    {trialPoints::all, "all"}
});

namespace
{
    //- A keyword of controlPoints
    const Foam::dcpRBFKeyword& key(const char* name)
    {
        return Foam::dcpRBFKeywords::get("controlPoints", name);
    }

    //- The choices of trialPoints: the Enum's names
    const Foam::dcpRBFKeyword::choicesFrom trialPointsChoices
    (
        "controlPoints", "trialPoints",
        Foam::dcpRBFErrorGuidedSettings::trialPointsNames
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFErrorGuidedSettings::dcpRBFErrorGuidedSettings
(
    const dictionary& dict
)
{
    const dcpRBFDictReader r(dict);
    swapBlendSteps = r.getLabel(key("swapBlendSteps"));
    trialAt = r.getEnum(key("trialPoints"), trialPointsNames);
    trialBackoff = r.getLabel(key("trialBackoff"));
    trialQualityDrop = r.getScalar(key("trialQualityDrop"));
}


Foam::dcpRBFErrorGuidedSwaps::dcpRBFErrorGuidedSwaps
(
    const dcpRBFContext& context,
    dcpRBFControlPoints& controlPoints,
    dcpRBFQualityMeasurement& quality,
    dcpRBFInterpolation& interpolation
)
:
    dcpRBFSwapRule(context, controlPoints, quality, interpolation),
    settings_
    (
        refCast<const dcpRBFErrorGuidedSettings>
        (
            context.settings().selection().swapRule()
        )
    ),
    trials_(controlPoints.set()),
    blend_(settings_.swapBlendSteps),
    schedule_
    (
        settings_.trialBackoff,
        dcpRBFErrorGuidedSettings::maxTrialWait(),
        settings_.trialQualityDrop
    ),
    windowInterpolation_(context, interpolation)
{
    controlPoints_.blendWith(blend_);
    controlPoints_.state().add
    (
        [this](dictionary& state) { storeState(state); }
    );
    if (controlPoints_.restored())
    {
        readState();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFErrorGuidedSettings::maxTrialWait()
{
    return label(key("trialBackoff").hi);
}


Foam::label Foam::dcpRBFErrorGuidedSettings::nSwapDefault() const
{
    return label(key("nSwap").deflt);
}


Foam::label Foam::dcpRBFErrorGuidedSwaps::lowestCells(const label nCells) const
{
    return
        max
        (
            dcpRBFSwapRule::lowestCells(nCells),
            dcpRBFTrialMesh::windowSize(nCells) + 1
        );
}


bool Foam::dcpRBFErrorGuidedSwaps::measuresFirst() const
{
    // trials due, not a rescue (the last step's mesh had no inverted cell),
    // and the last step's measurement to pick the window from
    const dcpRBFQualityRegion::summary& last = quality_.last();
    return !(canTrial(false) && last.nCells > 0 && last.nInverted == 0);
}


void Foam::dcpRBFErrorGuidedSwaps::afterInterpolate
(
    const dcprbf::Values& d,
    dcpRBFStepState& step,
    const bool measured
)
{
    // waiting after undone trials unless the mesh got worse since
    const bool waitEnded =
        measured && schedule_.endWaitIfWorse(quality_.last().minQuality);
    const dcprbf::TrialSchedule::Saved before(schedule_.save());
    if
    (
        trySwaps(d, step, measured) == 0
     && !measured
     && quality_.last().nInverted > 0
    )
    {
        // the mesh without swaps (measured) has inverted cells: the
        // rescue, backing off as if the trials had not been made
        schedule_.restore(before);
        trySwaps(d, step, true);
    }
    step.waitEnded = waitEnded;
}


void Foam::dcpRBFErrorGuidedSwaps::endStep(const scalar minQuality)
{
    if (trials_.started())
    {
        // this step's swaps were kept
        schedule_.kept();
        trials_.confirm();
    }
    schedule_.endStep(minQuality);
    blend_.advance();
    if (context_.time().writeTime())
    {
        // the phased-out set refactorized from its indices, as a restart
        // makes it (restarts are exact)
        try
        {
            blend_.refresh(controlPoints_.set());
        }
        catch (const dcprbf::Error& e)
        {
            WarningInFunction
                << "Time " << context_.time().timeName() << ": the control"
                << " set being phased out could not be refactorized from its"
                << " indices (" << e.what() << "); a restart from this time"
                << " will fail: " << controlPoints_.whatToDo(e).c_str()
                << endl;
        }
    }
}


// ************************************************************************* //
