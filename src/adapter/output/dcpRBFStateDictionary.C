/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFStateDictionary.H"
#include "Time.H"
#include "IStringStream.H"
#include "OStringStream.H"

#include <limits>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFStateDictionary::dcpRBFStateDictionary
(
    const word& name,
    const objectRegistry& mesh,
    filler fill
)
:
    IOdictionary
    (
        IOobject
        (
            name,
            mesh.time().timeName(),
            "uniform",
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        )
    ),
    fill_(1, std::move(fill))
{
    // The entries are text whatever format the header names (the case's
    // writeFormat): read as binary, a list would be read as raw bytes, which
    // a dictionary entry cannot give. Parsed again as text, at full precision
    if (size())
    {
        OStringStream text;
        text.precision(std::numeric_limits<double>::max_digits10);
        dictionary::write(text, false);
        IStringStream is(text.str());
        clear();
        dictionary::read(is);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dcpRBFStateDictionary::writeData(Ostream& os) const
{
    // At full precision whatever writePrecision, so that a restart
    // continues exactly (the entries are made as text at the default
    // precision, then written at the stream's)
    const int digits = std::numeric_limits<double>::max_digits10;
    dictionary state(*this);
    {
        // the default back however the fills end (FatalError may throw)
        struct scope
        {
            const unsigned was;
            explicit scope(const unsigned d) : was(IOstream::defaultPrecision(d)) {}
            ~scope() { IOstream::defaultPrecision(was); }
        } fullDefault(digits);
        for (const filler& fill : fill_)
        {
            fill(state);
        }
    }
    const int osDigits = os.precision(digits);
    state.write(os, false);
    os.precision(osDigits);
    return os.good();
}


// ************************************************************************* //
