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

namespace
{
    //- A keyword of controlPoints
    const Foam::dcpRBFKeyword& key(const char* name)
    {
        return Foam::dcpRBFKeywords::get("controlPoints", name);
    }

    //- The choices of selection and selectOn: the Enums' names
    const Foam::dcpRBFKeyword::choicesFrom modeChoices
    (
        "controlPoints", "selection",
        Foam::dcpRBFSelectionSettings::modeNames
    );
    const Foam::dcpRBFKeyword::choicesFrom targetChoices
    (
        "controlPoints", "selectOn",
        Foam::dcpRBFSelectionSettings::targetNames
    );

    //- The scope of the keywords a selection allows
    Foam::dcpRBFKeyword::scope scopeOf
    (
        const Foam::dcpRBFSelectionSettings::mode m
    )
    {
        using mode = Foam::dcpRBFSelectionSettings::mode;
        using scope = Foam::dcpRBFKeyword::scope;
        return
            m == mode::all ? scope::always
          : m == mode::greedy ? scope::reduced : scope::dynamic;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFSelectionSettings::dcpRBFSelectionSettings(const dictionary& dict)
{
    const dcpRBFDictReader r(dict);
    r.checkKeywordsOf("controlPoints");
    selection = r.getEnum(key("selection"), modeNames);
    selectionGiven = dict.found("selection");
    maxPointsGiven = dict.found("maxPoints");
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
    // the swap rule's own keywords, read by its settings (in selection all
    // and greedy too: the default rule's give nSwap's default there)
    swapRule_.reset(dcpRBFSwapRuleSettings::New(dict).ptr());
    nSwap = r.getLabel(key("nSwap"), swapRule_->nSwapDefault());
    protectSteps = r.getLabel(key("protectSteps"));
    r.checkScope
    (
        "controlPoints", modeNames.toc(), scopeOf(selection),
        swapRule_->type(), nSwap > 0
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFSelectionSettings::chooseDefault(const label nCandidates)
{
    if (!selectionGiven && nCandidates > maxPoints)
    {
        selection = mode::dynamic;
    }
    if (!maxPointsGiven && nCandidates > 0)
    {
        const label before = maxPoints;
        maxPoints =
            max(minPoints, min(maxPoints, max(label(100), basisBudget/nCandidates)));
        maxPointsBounded = maxPoints < before;
    }
}


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
