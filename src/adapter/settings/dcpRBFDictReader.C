/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFDictReader.H"
#include "Switch.H"
#include "wordRes.H"
#include "OStringStream.H"
#include "dcpRBFVersion.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFDictReader::dcpRBFDictReader(const dictionary& dict)
:
    dict_(dict)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::ITstream* Foam::dcpRBFDictReader::tokens
(
    const word& keyword,
    const string& expected
) const
{
    const entry* e = dict_.findEntry(keyword, keyType::LITERAL);
    if (!e)
    {
        return nullptr;
    }
    if (e->isDict())
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << keyword << " must be " << expected.c_str()
            << "; got a sub-dictionary" << exit(FatalIOError);
    }
    ITstream& is = e->stream();
    is.rewind();
    return &is;
}


const Foam::token* Foam::dcpRBFDictReader::single
(
    const word& keyword,
    const string& expected
) const
{
    ITstream* is = tokens(keyword, expected);
    if (!is)
    {
        return nullptr;
    }
    if (is->size() != 1)
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << keyword << " must be " << expected.c_str()
            << "; got " << is->size() << " tokens: " << asWritten(*is).c_str()
            << exit(FatalIOError);
    }
    return &(*is)[0];
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dcpRBFDictReader::getSwitch(const dcpRBFKeyword& k) const
{
    return getSwitch(k.name, k.deflt != 0);
}


Foam::label Foam::dcpRBFDictReader::getChoice(const dcpRBFKeyword& k) const
{
    return getChoice(k.name, k.choiceList(), k.defaultWord);
}


Foam::scalar Foam::dcpRBFDictReader::getScalar(const dcpRBFKeyword& k) const
{
    return getScalar(k, k.deflt, k.lo);
}


Foam::scalar Foam::dcpRBFDictReader::getScalar
(
    const dcpRBFKeyword& k,
    const scalar deflt,
    const scalar lo
) const
{
    dcpRBFKeyword bounds(k);
    bounds.lo = lo;
    const string range("a number in " + bounds.rangeText());
    const token* t = single(k.name, range);
    if (t && !t->isNumber())
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << k.name << " must be " << range.c_str()
            << "; got " << *t << exit(FatalIOError);
    }
    const scalar x(t ? t->number() : deflt);
    if (!bounds.within(x))
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << k.name << " must be " << range.c_str()
            << ", got " << x << exit(FatalIOError);
    }
    return x;
}


Foam::label Foam::dcpRBFDictReader::getLabel(const dcpRBFKeyword& k) const
{
    return getLabel(k, label(k.deflt));
}


Foam::label Foam::dcpRBFDictReader::getLabel
(
    const dcpRBFKeyword& k,
    const label deflt
) const
{
    return getLabel
    (
        k.name, deflt, label(k.lo), k.bounded() ? label(k.hi) : labelMax
    );
}


bool Foam::dcpRBFDictReader::getSwitch
(
    const word& keyword,
    const bool deflt
) const
{
    const token* tp = single(keyword, "a switch (true/false, on/off, yes/no)");
    if (!tp)
    {
        return deflt;
    }
    const token& t = *tp;
    const Switch sw
    (
        t.isWord() ? dcpRBFCompat::findSwitch(t.wordToken()) : Switch(Switch::INVALID)
    );
    if (!t.isWord() || sw.type() == Switch::INVALID)
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
    const token* t = single(keyword, "one of " + Foam::name(allowed.size()) + " words");
    if (t && !t->isWord())
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << keyword << " must be a word; got " << *t
            << ". Allowed values: " << allowed << exit(FatalIOError);
    }
    const word w(t ? t->wordToken() : deflt);
    const label i = allowed.find(w);
    if (i < 0)
    {
        FatalIOErrorInFunction(dict_)
            << "Unknown " << keyword << " " << w << ". Allowed values: "
            << allowed << exit(FatalIOError);
    }
    return i;
}


Foam::label Foam::dcpRBFDictReader::getLabel
(
    const word& keyword,
    const label deflt,
    const label lo,
    const label hi
) const
{
    const string range("a whole number in [" + Foam::name(lo) + ", " + Foam::name(hi) + "]");
    const token* t = single(keyword, range);
    if (t && !t->isLabel())
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << keyword << " must be " << range.c_str()
            << "; got " << *t << exit(FatalIOError);
    }
    const label n(t ? t->labelToken() : deflt);
    if (n < lo || n > hi)
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << keyword << " must be " << range.c_str()
            << ", got " << n << exit(FatalIOError);
    }
    return n;
}


Foam::wordRes Foam::dcpRBFDictReader::getWordRes
(
    const word& keyword,
    const bool allowEmpty
) const
{
    const string expected
    (
        "a list of patch names, regular expressions or groups, e.g. "
      + keyword + " (wing \"flap.*\")"
    );
    ITstream* is = tokens(keyword, expected);
    if (!is)
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << keyword << " missing: " << expected.c_str()
            << exit(FatalIOError);
    }
    // ( word|string ... ), or N( ... ): anything else is not such a list
    label k = 0;
    if (is->size() && (*is)[0].isLabel()) ++k;
    bool ok = is->size() >= k + 2 && (*is)[k] == token::BEGIN_LIST
        && (*is)[is->size() - 1] == token::END_LIST;
    for (label i = k + 1; ok && i < is->size() - 1; ++i)
    {
        ok = (*is)[i].isWord() || (*is)[i].isString();
    }
    if (!ok)
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << keyword << " must be " << expected.c_str()
            << "; got " << asWritten(*is).c_str() << exit(FatalIOError);
    }
    is->rewind();
    const wordRes matchers(*is);
    if (matchers.empty() && !allowEmpty)
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << keyword << " is an empty list: " << expected.c_str()
            << exit(FatalIOError);
    }
    return matchers;
}


Foam::vector Foam::dcpRBFDictReader::getTriple
(
    const word& keyword,
    const string& expected
) const
{
    ITstream* is = tokens(keyword, expected);
    bool ok =
        is && is->size() == 5 && (*is)[0] == token::BEGIN_LIST
     && (*is)[4] == token::END_LIST;
    for (label i = 1; ok && i < 4; ++i)
    {
        ok = (*is)[i].isNumber();
    }
    if (!ok)
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << keyword << " must be " << expected.c_str()
            << "; got " << (is ? asWritten(*is) : string("nothing")).c_str()
            << exit(FatalIOError);
    }
    return vector((*is)[1].number(), (*is)[2].number(), (*is)[3].number());
}


Foam::point Foam::dcpRBFDictReader::getPoint(const word& keyword) const
{
    return getTriple(keyword, "a point (x y z), e.g. " + keyword + " (0.25 0 0)");
}


Foam::vector Foam::dcpRBFDictReader::getDirection(const word& keyword) const
{
    const string expected
    (
        "a non-zero vector (x y z), e.g. " + keyword + " (0 1 0)"
    );
    const vector v(getTriple(keyword, expected));
    if (!(mag(v) > VSMALL))
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << keyword << " must be " << expected.c_str()
            << "; got (0 0 0)" << exit(FatalIOError);
    }
    return v/mag(v);
}


Foam::string Foam::dcpRBFDictReader::asWritten
(
    const ITstream& is,
    const int digits
)
{
    OStringStream os;
    os.precision(digits);
    forAll(is, i)
    {
        os << (i ? " " : "") << is[i];
    }
    return os.str();
}


Foam::word Foam::dcpRBFDictReader::getName(const dcpRBFKeyword& k) const
{
    const token* t = single(k.name, "a name, e.g. " + word(k.name) + " wing");
    if (!t)
    {
        return word();
    }
    if (!t->isWord())
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << k.name << " must be a name, e.g. " << k.name
            << " wing; got " << *t << exit(FatalIOError);
    }
    return t->wordToken();
}


Foam::scalar Foam::dcpRBFDictReader::getLength
(
    const dcpRBFKeyword& k,
    const word& unitWord,
    const std::function<scalar()>& unit,
    const scalar size,
    const scalar deflt
) const
{
    const word keyword(k.name);
    if (!dict_.found(keyword))
    {
        return deflt;
    }
    ITstream& is = dict_.lookup(keyword);
    if (is.empty() || !is[0].isNumber())
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword " << keyword << " must be a length [m] or \"factor "
            << unitWord << "\"; got " << asWritten(is).c_str()
            << exit(FatalIOError);
    }
    const scalar factor(readScalar(is));
    scalar length = factor;
    if (!is.eof())
    {
        const token t(is);
        if (!t.isWord() || t.wordToken() != unitWord)
        {
            FatalIOErrorInFunction(dict_)
                << "Keyword " << keyword << ": a length [m] or \"factor "
                << unitWord << "\"; got " << t << " after " << factor
                << ". Allowed unit word: " << unitWord << exit(FatalIOError);
        }
        length = factor*unit();
    }
    checkLength(k, length, size);
    return length;
}


// ************************************************************************* //
