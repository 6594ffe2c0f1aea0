/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFScanOrder.H"
#include "MortonOrder.hpp"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::dcpRBFScanOrder::of
(
    const polyMesh& mesh,
    const pointField& points0,
    const std::vector<label>& cells
)
{
    std::vector<double> key;
    key.reserve(3*cells.size());
    for (const label celli : cells)
    {
        const point& x = points0[mesh.faces()[mesh.cells()[celli][0]][0]];
        key.insert(key.end(), {x.x(), x.y(), x.z()});
    }
    const std::vector<int> order(dcprbf::mortonOrder(key.data(), cells.size()));
    labelList ordered(label(cells.size()));
    forAll(ordered, i)
    {
        ordered[i] = cells[order[i]];
    }
    return ordered;
}


Foam::FixedList<Foam::scalar, 3> Foam::dcpRBFScanOrder::centre
(
    const labelListList& cellPoints,
    const dcpRBFPlaneProjection& projection,
    const pointField& points0,
    const label celli
)
{
    const labelList& cp = cellPoints[celli];
    vector c(Zero);
    for (const label pi : cp) c += points0[pi];
    c /= cp.size();
    FixedList<scalar, 3> x;
    projection.toCore(c, x.data());
    return x;
}


// ************************************************************************* //
