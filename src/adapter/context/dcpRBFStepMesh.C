/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFStepMesh.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFStepMesh::dcpRBFStepMesh(pointVectorField& field)
:
    field_(field),
    version_(0),
    nVersions_(1)
{}


Foam::dcpRBFStepMesh::loan::loan(dcpRBFStepMesh& mesh, vectorField& field)
:
    mesh_(mesh),
    field_(field),
    version_(mesh.version_)
{
    // (exchanged, not copied)
    mesh_.change().primitiveFieldRef().swap(field_);
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::dcpRBFStepMesh::loan::~loan()
{
    mesh_.field_.primitiveFieldRef().swap(field_);
    mesh_.version_ = version_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::pointVectorField& Foam::dcpRBFStepMesh::change()
{
    version_ = nVersions_++;
    return field_;
}


void Foam::dcpRBFStepMesh::unchanged(const label v)
{
    version_ = v;
}


void Foam::dcpRBFStepMesh::restore(copy&& c)
{
    field_.primitiveFieldRef().transfer(c.displacement);
    version_ = c.version;
}


// ************************************************************************* //
