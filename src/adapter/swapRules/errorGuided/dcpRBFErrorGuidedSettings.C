/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFErrorGuidedSettings.H"
#include "dcpRBFDictReader.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFErrorGuidedSettings::maxTrialWait()
{
    return label(key("trialBackoff").hi);
}


Foam::label Foam::dcpRBFErrorGuidedSettings::nSwapDefault() const
{
    return label(key("nSwap").deflt);
}


// ************************************************************************* //
