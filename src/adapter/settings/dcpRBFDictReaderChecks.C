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

#include <algorithm>
#include <cctype>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    //- The edit distance of a and b, letters' case ignored (Levenshtein:
    //  insertions, deletions and substitutions)
    std::size_t editDistance(const std::string& a, const std::string& b)
    {
        std::vector<std::size_t> row(b.size() + 1);
        for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
        for (std::size_t i = 1; i <= a.size(); ++i)
        {
            std::size_t diagonal = row[0];
            row[0] = i;
            for (std::size_t j = 1; j <= b.size(); ++j)
            {
                const std::size_t above = row[j];
                const bool same = std::tolower(a[i - 1]) == std::tolower(b[j - 1]);
                row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + !same});
                diagonal = above;
            }
        }
        return row[b.size()];
    }

    //- The known keyword nearest to a misspelt one, if near enough to be a
    //  slip (at most 2 edits, or a third of its length); else empty
    Foam::word nearest(const Foam::word& given, const Foam::wordList& known)
    {
        Foam::word best;
        std::size_t bestDistance = std::max<std::size_t>(2, given.size()/3) + 1;
        for (const Foam::word& w : known)
        {
            const std::size_t d = editDistance(given, w);
            if (d < bestDistance)
            {
                best = w;
                bestDistance = d;
            }
        }
        return best;
    }
}


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
            const word guess(nearest(e.keyword(), known));
            FatalIOErrorInFunction(dict_)
                << "Unknown keyword " << e.keyword() << " in "
                << dict_.dictName()
                << (guess.empty() ? string() : " (did you mean " + guess + "?)").c_str()
                << ". Allowed keywords: " << allowed.c_str()
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
