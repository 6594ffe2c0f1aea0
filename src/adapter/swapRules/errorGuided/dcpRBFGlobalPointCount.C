/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFGlobalPointCount.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFGlobalPointCount::dcpRBFGlobalPointCount(const polyMesh& mesh)
:
    mesh_(mesh),
    masterPointsMade_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFGlobalPointCount::count(const labelUList& points)
{
    if (!Pstream::parRun())
    {
        return points.size();
    }
    if (!masterPointsMade_)
    {
        masterPoints_ = syncTools::getMasterPoints(mesh_);
        masterPointsMade_ = true;
    }
    // a point in any processor's list, counted by its master
    // (labels: OpenFOAM's exchange of bools trips GCC's allocation-size
    // warning, an error in CI)
    labelList in(mesh_.nPoints(), 0);
    for (const label pointi : points)
    {
        in[pointi] = 1;
    }
    syncTools::syncPointList(mesh_, in, maxEqOp<label>(), label(0));
    label n = 0;
    forAll(in, pointi)
    {
        if (in[pointi] && masterPoints_.test(pointi))
        {
            ++n;
        }
    }
    return returnReduce(n, sumOp<label>());
}


// ************************************************************************* //
