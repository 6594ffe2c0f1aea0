/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFSelectionSettings.H"
#include "dcpRBFDictReader.H"
#include "Switch.H"

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

const Foam::Enum<Foam::dcpRBFSelectionSettings::trialPoints>
Foam::dcpRBFSelectionSettings::trialPointsNames
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
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFSelectionSettings::dcpRBFSelectionSettings(const dictionary& dict)
{
    const dcpRBFDictReader r(dict);
    r.checkKeywordsOf("controlPoints");
    using scope = dcpRBFKeyword::scope;
    const wordList keywords(dcpRBFKeywords::names("controlPoints"));
    const wordList dynamicKeywords
    (
        dcpRBFKeywords::namesOnly("controlPoints", scope::dynamic)
    );

    selection = r.getEnum(key("selection"), modeNames);
    tolerance = r.getScalar(key("tolerance"));
    minPoints = r.getLabel(key("minPoints"));
    maxPoints = r.getLabel(key("maxPoints"), max(label(key("maxPoints").deflt), minPoints));
    if (minPoints > maxPoints)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword minPoints (" << minPoints << ") exceeds maxPoints ("
            << maxPoints << ")" << exit(FatalIOError);
    }
    doubleEdged = r.getSwitch(key("doubleEdged"));
    selectOn = r.getEnum(key("selectOn"), targetNames);
    // (default and lower bound from tolerance: the table says so)
    {
        dcpRBFKeyword k(key("reselectTolerance"));
        k.lowIncluded = true;
        reselectTolerance =
            r.getScalar(k, max(min(10*tolerance, 1.0), tolerance), tolerance);
    }
    swapRule = key("swapRule").choiceList()[r.getChoice(key("swapRule"))];
    nSwap = r.getLabel
    (
        key("nSwap"), swapRule == "errorGuided" ? label(key("nSwap").deflt) : 1
    );
    protectSteps = r.getLabel(key("protectSteps"));
    swapBlendSteps = r.getLabel(key("swapBlendSteps"));
    trialAt = r.getEnum(key("trialPoints"), trialPointsNames);
    trialBackoff = r.getLabel(key("trialBackoff"));
    trialQualityDrop = r.getScalar(key("trialQualityDrop"));
    for (const word& k : keywords)
    {
        // a swap rule's own keywords
        const char* rule = key(k.c_str()).rule;
        if (!rule || !dict.found(k))
        {
            continue;
        }
        if (swapRule != rule)
        {
            FatalIOErrorInFunction(dict)
                << "Keyword " << k << " has no effect with swapRule "
                << swapRule << ". It belongs to swapRule " << rule
                << exit(FatalIOError);
        }
        if (nSwap == 0)
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFSelectionSettings::setDependsOn(dictionary& d) const
{
    // as strings: written quoted, read back as written
    const auto put = [&](const word& key, const std::string& value)
    {
        d.set(key, string(value));
    };
    put("selection", selectionName());
    if (!everyCandidate())
    {
        put("tolerance", Foam::name(tolerance));
        put("minPoints", Foam::name(minPoints));
        put("maxPoints", Foam::name(maxPoints));
        put("doubleEdged", Switch(doubleEdged).c_str());
        put("selectOn", targetNames[selectOn]);
    }
}


// ************************************************************************* //
