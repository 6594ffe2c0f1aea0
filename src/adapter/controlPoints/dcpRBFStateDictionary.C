/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFStateDictionary.H"
#include "Time.H"

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
    fill_(std::move(fill))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dcpRBFStateDictionary::writeData(Ostream& os) const
{
    dictionary state(*this);
    fill_(state);
    state.write(os, false);
    return os.good();
}


// ************************************************************************* //
