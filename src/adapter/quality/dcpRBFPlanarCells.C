/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFPlanarCells.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFPlanarCells::dcpRBFPlanarCells
(
    const polyMesh& mesh,
    const labelUList& cells,
    const pointField& points0
)
:
    axis0_(0),
    axis1_(1),
    polygonStart_(1, 0)
{
    const Vector<label> geometricD(mesh.geometricD());
    label empty = -1, nEmpty = 0;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (geometricD[d] < 0)
        {
            empty = d;
            ++nEmpty;
        }
    }
    const bool twoD = nEmpty == 1 && mesh.nSolutionD() == 2;
    if (twoD)
    {
        axis0_ = direction((empty + 1) % 3);
        axis1_ = direction((empty + 2) % 3);
    }
    forAll(cells, i)
    {
        if (twoD && appendPolygon(mesh, cells[i], points0, direction(empty)))
        {
            planar_.append(i);
            polygonStart_.push_back(polygonPoints_.size());
        }
        else
        {
            others_.append(i);
        }
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::dcpRBFPlanarCells::appendPolygon
(
    const polyMesh& mesh,
    const label celli,
    const pointField& points0,
    const direction empty
)
{
    const cell& c = mesh.cells()[celli];
    const faceList& faces = mesh.faces();
    label caps[2] = {-1, -1};
    label nCaps = 0;
    for (const label facei : c)
    {
        const vector n(faces[facei].areaNormal(points0));
        if (mag(n[empty]) > (1 - 1e-6)*mag(n))
        {
            if (nCaps == 2) return false;
            caps[nCaps++] = facei;
        }
    }
    if (nCaps != 2) return false;
    const face& a = faces[caps[0]];
    const face& b = faces[caps[1]];
    if (a.size() != b.size() || c.size() != a.size() + 2) return false;
    for (const label facei : c)
    {
        if (facei != caps[0] && facei != caps[1] && faces[facei].size() != 4) return false;
    }

    // every point of the first cap has its own in-plane twin in the second
    const boundBox box(points0, a, false);
    const scalar tol = 1e-8*mag(box.span());
    labelList twin(a.size(), -1);
    forAll(a, i)
    {
        for (const label pb : b)
        {
            if
            (
                mag(points0[a[i]][axis0_] - points0[pb][axis0_]) <= tol
             && mag(points0[a[i]][axis1_] - points0[pb][axis1_]) <= tol
            )
            {
                if (twin[i] >= 0) return false;   // two candidates
                twin[i] = pb;
            }
        }
        if (twin[i] < 0 || twin.find(twin[i]) < i) return false;   // none, or shared
    }

    // and each side face joins an edge of the first cap to its twins (not
    // a twisted prism)
    forAll(a, i)
    {
        const label j = a.fcIndex(i);
        const label ends[4] = {a[i], a[j], twin[i], twin[j]};
        bool joined = false;
        for (const label facei : c)
        {
            const face& f = faces[facei];
            joined = joined
             || (
                    facei != caps[0] && facei != caps[1]
                 && f.found(ends[0]) && f.found(ends[1])
                 && f.found(ends[2]) && f.found(ends[3])
                );
        }
        if (!joined) return false;
    }
    polygonPoints_.insert(polygonPoints_.end(), a.begin(), a.end());
    return true;
}


// ************************************************************************* //
