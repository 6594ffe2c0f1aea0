/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFSwapRuleSettings.H"
#include "dcpRBFDictReader.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dcpRBFSwapRuleSettings, 0);
    defineRunTimeSelectionTable(dcpRBFSwapRuleSettings, dictionary);

    //- The choices of swapRule: the names of the table
    static const dcpRBFKeyword::choicesFrom swapRuleChoices
    (
        "controlPoints", "swapRule", &dcpRBFSwapRuleSettings::names
    );
}


// * * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::dcpRBFSwapRuleSettings> Foam::dcpRBFSwapRuleSettings::New
(
    const dictionary& dict
)
{
    const dcpRBFKeyword& k = dcpRBFKeywords::get("controlPoints", "swapRule");
    const word name(k.choiceList()[dcpRBFDictReader(dict).getChoice(k)]);
    return autoPtr<dcpRBFSwapRuleSettings>
    (
        dictionaryConstructorTablePtr_->cfind(name)()(dict)
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::dcpRBFSwapRuleSettings::names()
{
    return
        dictionaryConstructorTablePtr_
      ? dictionaryConstructorTablePtr_->sortedToc() : wordList();
}


// ************************************************************************* //
