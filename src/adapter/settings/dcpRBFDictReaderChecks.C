/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFDictReader, continued: the checks of a dictionary against the
    keyword table (unknown keywords, a keyword's scope and rule, a length's
    bounds).

\*---------------------------------------------------------------------------*/

#include "dcpRBFDictReader.H"
#include "Switch.H"
#include "wordRes.H"
#include "OStringStream.H"
#include "dcpRBFVersion.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFDictReader::checkKeywords(const wordList& known) const
{
    for (const entry& e : dict_)
    {
        if (!known.found(e.keyword()))
        {
            string allowed;
            for (const word& w : known)
            {
                allowed += (allowed.empty() ? "" : " ") + w;
            }
            FatalIOErrorInFunction(dict_)
                << "Unknown keyword " << e.keyword() << " in "
                << dict_.dictName() << ". Allowed keywords: " << allowed.c_str()
                << exit(FatalIOError);
        }
    }
}


void Foam::dcpRBFDictReader::checkKeywordsOf(const word& dictionaryName) const
{
    checkKeywords(dcpRBFKeywords::names(dictionaryName));
}


void Foam::dcpRBFDictReader::checkScope
(
    const word& dictionaryName,
    const wordList& selections,
    const dcpRBFKeyword::scope selected,
    const word& rule,
    const bool ruleActs
) const
{
    const auto given = [&](const dcpRBFKeyword& k)
    {
        return dictionaryName == k.dictionary && dict_.found(k.name);
    };
    for (const dcpRBFKeyword& k : dcpRBFKeywords::all())
    {
        // a swap rule's own keywords
        if (!k.rule || !given(k))
        {
            continue;
        }
        if (rule != k.rule)
        {
            FatalIOErrorInFunction(dict_)
                << "Keyword " << k.name << " has no effect with swapRule "
                << rule << ". It belongs to swapRule " << k.rule
                << exit(FatalIOError);
        }
        if (!ruleActs)
        {
            FatalIOErrorInFunction(dict_)
                << "Keyword " << k.name << " has no effect with nSwap 0 (no"
                << " trial swaps). It needs nSwap >= 1" << exit(FatalIOError);
        }
    }
    for (const dcpRBFKeyword& k : dcpRBFKeywords::all())
    {
        if (!given(k) || k.allowedWith <= selected)
        {
            continue;
        }
        const label s = label(k.allowedWith);
        if (selected == dcpRBFKeyword::scope::always)
        {
            string allowed;
            for (label i = s; i < selections.size(); ++i)
            {
                allowed += (i > s ? ", " : "") + selections[i];
            }
            FatalIOErrorInFunction(dict_)
                << "Keyword " << k.name << " has no effect with selection "
                << selections[label(selected)] << ". Allowed selections"
                << " using it: " << allowed.c_str() << exit(FatalIOError);
        }
        FatalIOErrorInFunction(dict_)
            << "Keyword " << k.name << " has no effect with selection "
            << selections[label(selected)] << ". It belongs to selection "
            << selections[s] << exit(FatalIOError);
    }
}


void Foam::dcpRBFDictReader::checkLength
(
    const dcpRBFKeyword& k,
    const scalar length,
    const scalar size
) const
{
    if (!(length > 0))
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << k.name << " must be > 0 [m], got " << length
            << exit(FatalIOError);
    }
    // Far outside the mesh's size a length is no length for it (and its
    // square overflows in the searches)
    if (!(length >= k.lo*size && length <= k.hi*size))
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << k.name << " " << Foam::name(length).c_str()
            << " is no length for this mesh (its bounding box's diagonal: "
            << Foam::name(size).c_str() << "): allowed "
            << Foam::name(k.lo*size).c_str() << " to "
            << Foam::name(k.hi*size).c_str() << " [m]"
            << (k.advice ? ", in practice " : "")
            << (k.advice ? k.advice : "") << exit(FatalIOError);
    }
}


// ************************************************************************* //
