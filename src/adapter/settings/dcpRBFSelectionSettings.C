/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFSelectionSettings.H"
#include "dcpRBFDictReader.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::Enum<Foam::dcpRBFSelectionSettings::mode>
Foam::dcpRBFSelectionSettings::modeNames
({
    {mode::all, "all"},
    {mode::greedy, "greedy"},
    {mode::dynamic, "dynamic"}
});

const Foam::Enum<Foam::dcpRBFSelectionSettings::target>
Foam::dcpRBFSelectionSettings::targetNames
({
    {target::displacement, "displacement"},
    {target::unit, "unit"}
});

const Foam::Enum<Foam::dcpRBFSelectionSettings::rule>
Foam::dcpRBFSelectionSettings::ruleNames
({
    {rule::errorGuided, "errorGuided"},
    {rule::nearest, "nearest"}
});

const Foam::Enum<Foam::dcpRBFSelectionSettings::trialPoints>
Foam::dcpRBFSelectionSettings::trialPointsNames
({
    {trialPoints::window, "window"},
    {trialPoints::all, "all"}
});

const Foam::wordList Foam::dcpRBFSelectionSettings::keywords
({
    "selection", "tolerance", "minPoints", "maxPoints", "doubleEdged",
    "selectOn", "reselectTolerance", "nSwap", "protectSteps", "swapRule",
    "swapBlendSteps", "trialPoints", "trialBackoff", "trialQualityDrop"
});

namespace
{
    //- The keywords of selection dynamic alone, and of its swapRule
    //  errorGuided alone
    const Foam::wordList dynamicKeywords
    ({
        "nSwap", "protectSteps", "swapRule", "swapBlendSteps", "trialPoints",
        "trialBackoff", "trialQualityDrop"
    });
    const Foam::wordList errorGuidedKeywords
    ({
        "swapBlendSteps", "trialPoints", "trialBackoff", "trialQualityDrop"
    });
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFSelectionSettings::dcpRBFSelectionSettings(const dictionary& dict)
{
    const dcpRBFDictReader r(dict);
    r.checkKeywords(keywords);

    selection = r.getEnum("selection", modeNames, mode::all);
    tolerance = r.getScalar("tolerance", 1e-3, 0, 1);
    minPoints = r.getLabel("minPoints", 0, 0, labelMax);
    maxPoints = r.getLabel("maxPoints", max(2000, minPoints), 1, labelMax);
    if (minPoints > maxPoints)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword minPoints (" << minPoints << ") exceeds maxPoints ("
            << maxPoints << ")" << exit(FatalIOError);
    }
    doubleEdged = r.getSwitch("doubleEdged", false);
    selectOn = r.getEnum("selectOn", targetNames, target::displacement);
    reselectTolerance =
        r.getScalar("reselectTolerance", max(min(10*tolerance, 1.0), tolerance), tolerance, GREAT, true);
    swapRule = r.getEnum("swapRule", ruleNames, rule::errorGuided);
    nSwap = r.getLabel("nSwap", swapRule == rule::errorGuided ? 4 : 1, 0, 1000);
    protectSteps = r.getLabel("protectSteps", 3, 0, 1000000);
    swapBlendSteps = r.getLabel("swapBlendSteps", 4, 1, 1000);
    trialAt = r.getEnum("trialPoints", trialPointsNames, trialPoints::window);
    trialBackoff = r.getLabel("trialBackoff", trialBackoff, 1, maxTrialWait);
    trialQualityDrop =
        r.getScalar("trialQualityDrop", trialQualityDrop, 0, 1);
    for (const word& k : errorGuidedKeywords)
    {
        if (swapRule == rule::nearest && dict.found(k))
        {
            FatalIOErrorInFunction(dict)
                << "Keyword " << k << " has no effect with swapRule nearest."
                << " It belongs to swapRule errorGuided" << exit(FatalIOError);
        }
        if (nSwap == 0 && dict.found(k))
        {
            FatalIOErrorInFunction(dict)
                << "Keyword " << k << " has no effect with nSwap 0 (no trial"
                << " swaps). It needs nSwap >= 1" << exit(FatalIOError);
        }
    }

    if (selection == mode::all)
    {
        for (const word& k : keywords)
        {
            if (k != "selection" && dict.found(k))
            {
                const bool dynamicOnly = dynamicKeywords.found(k);
                FatalIOErrorInFunction(dict)
                    << "Keyword " << k << " has no effect with selection all."
                    << " Allowed selections using it: "
                    << (dynamicOnly ? "dynamic" : "greedy, dynamic")
                    << exit(FatalIOError);
            }
        }
    }
    if (selection != mode::dynamic)
    {
        for (const word& k : dynamicKeywords)
        {
            if (dict.found(k))
            {
                FatalIOErrorInFunction(dict)
                    << "Keyword " << k << " has no effect with selection "
                    << modeNames[selection] << ". It belongs to"
                    << " selection dynamic" << exit(FatalIOError);
            }
        }
    }
}


// ************************************************************************* //
