/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFDictReader.H"
#include "Switch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFDictReader::dcpRBFDictReader(const dictionary& dict)
:
    dict_(dict)
{}


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


bool Foam::dcpRBFDictReader::getSwitch
(
    const word& keyword,
    const bool deflt
) const
{
    const entry* e = dict_.findEntry(keyword, keyType::LITERAL);
    if (!e)
    {
        return deflt;
    }
    const token t(e->stream());
    const Switch sw
    (
        t.isWord() ? Switch(t.wordToken(), true) : Switch(Switch::INVALID)
    );
    if (!t.isWord() || !sw.valid())
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << keyword << " must be a switch; got " << t
            << ". Allowed values: true/false, on/off, yes/no"
            << exit(FatalIOError);
    }
    return bool(sw);
}


Foam::label Foam::dcpRBFDictReader::getChoice
(
    const word& keyword,
    const wordList& allowed,
    const word& deflt
) const
{
    const word w(dict_.getOrDefault<word>(keyword, deflt));
    const label i = allowed.find(w);
    if (i < 0)
    {
        FatalIOErrorInFunction(dict_)
            << "Unknown " << keyword << " " << w << ". Allowed values: "
            << allowed << exit(FatalIOError);
    }
    return i;
}


Foam::scalar Foam::dcpRBFDictReader::getScalar
(
    const word& keyword,
    const scalar deflt,
    const scalar lo,
    const scalar hi
) const
{
    const scalar x(dict_.getOrDefault<scalar>(keyword, deflt));
    if (!(x > lo && x <= hi))
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << keyword << " must be in (" << lo << ", " << hi
            << "], got " << x << exit(FatalIOError);
    }
    return x;
}


Foam::label Foam::dcpRBFDictReader::getLabel
(
    const word& keyword,
    const label deflt,
    const label lo,
    const label hi
) const
{
    const label n(dict_.getOrDefault<label>(keyword, deflt));
    if (n < lo || n > hi)
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << keyword << " must be in [" << lo << ", " << hi
            << "], got " << n << exit(FatalIOError);
    }
    return n;
}


// ************************************************************************* //
