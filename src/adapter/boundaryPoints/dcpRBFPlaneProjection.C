/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFPlaneProjection.H"
#include "wedgePolyPatch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFPlaneProjection::dcpRBFPlaneProjection(const polyMesh& mesh)
:
    dim_(3),
    wedge_(false),
    axes_({0, 1, 2}),
    midPlane_(0),
    backPlane_(0),
    candidateBound_(0)
{
    bool wedge = false;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        wedge = wedge || isA<wedgePolyPatch>(pp);
    }
    wedge_ = wedge;
    if (!wedge && mesh.nSolutionD() == 3)
    {
        return;
    }
    if (mesh.nGeometricD() != 2 || (!wedge && mesh.nSolutionD() != 2))
    {
        FatalErrorInFunction
            << "dcpRBF supports 3D cases, 2D cases with one empty"
            << " direction and axisymmetric (wedge) ones; this mesh has "
            << mesh.nGeometricD() << " geometric and " << mesh.nSolutionD()
            << " solution directions (1D cases are not supported)"
            << exit(FatalError);
    }

    const Vector<label>& geomD = mesh.geometricD();
    direction k = 0;
    for (direction d = 0; d < 3; ++d)
    {
        if (geomD[d] == 1) axes_[k++] = d;
        else axes_[2] = d;
    }
    dim_ = 2;
    const boundBox& bb = mesh.bounds();
    midPlane_ = 0.5*(bb.min()[axes_[2]] + bb.max()[axes_[2]]);
    backPlane_ = bb.min()[axes_[2]];
    candidateBound_ = midPlane_;
    if (wedge)
    {
        // the centre plane; the axis's points (on both wedge planes, at
        // the centre plane to round-off) are candidates too
        backPlane_ = midPlane_;
        candidateBound_ = midPlane_ + 1e-8*mag(bb.span());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

dcprbf::Points Foam::dcpRBFPlaneProjection::toCore(const UList<vector>& v) const
{
    dcprbf::Points p(v.size(), 3);
    forAll(v, i)
    {
        toCore(v[i], p.row(i).data());
    }
    return p;
}


// ************************************************************************* //
