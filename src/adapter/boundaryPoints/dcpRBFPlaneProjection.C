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
    axes_({0, 1, 2}),
    midPlane_(0),
    backPlane_(0)
{
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<wedgePolyPatch>(pp))
        {
            FatalErrorInFunction
                << "Patch " << pp.name() << " is of type wedge: dcpRBF does"
                << " not support axisymmetric (wedge) cases. Supported: 3D"
                << " cases and 2D cases with one empty direction"
                << exit(FatalError);
        }
    }
    if (mesh.nSolutionD() == 3)
    {
        return;
    }
    if (mesh.nGeometricD() != 2 || mesh.nSolutionD() != 2)
    {
        FatalErrorInFunction
            << "dcpRBF supports 3D cases and 2D cases with one empty"
            << " direction; this mesh has " << mesh.nGeometricD()
            << " geometric and " << mesh.nSolutionD() << " solution"
            << " directions (axisymmetric wedge or 1D cases are not"
            << " supported)" << exit(FatalError);
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
