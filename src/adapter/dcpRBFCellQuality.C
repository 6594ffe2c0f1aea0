/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFCellQuality.H"
#include "TetQuality.hpp"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFCellQuality::dcpRBFCellQuality
(
    const polyMesh& mesh,
    dcprbf::TetQuality::Metric metric
)
:
    mesh_(mesh),
    metric_(metric)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dcpRBFCellQuality::cellQuality
(
    const label celli,
    const pointField& p0,
    const pointField& p
) const
{
    const cell& c = mesh_.cells()[celli];
    const faceList& faces = mesh_.faces();

    // Centres as plain averages (the same construction for both meshes)
    const auto centre = [](const face& f, const pointField& pts)
    {
        Eigen::Vector3d s(Eigen::Vector3d::Zero());
        for (const label pi : f) s += Eigen::Vector3d(pts[pi].x(), pts[pi].y(), pts[pi].z());
        return Eigen::Vector3d(s/f.size());
    };
    Eigen::Vector3d cc0(Eigen::Vector3d::Zero()), cc(Eigen::Vector3d::Zero());
    for (const label facei : c)
    {
        cc0 += centre(faces[facei], p0);
        cc += centre(faces[facei], p);
    }
    cc0 /= c.size();
    cc /= c.size();

    const auto vec = [](const point& x) { return Eigen::Vector3d(x.x(), x.y(), x.z()); };
    scalar q = GREAT;
    for (const label facei : c)
    {
        const face& f = faces[facei];
        const Eigen::Vector3d fc0(centre(f, p0)), fc(centre(f, p));
        forAll(f, i)
        {
            const label a = f[i], b = f.nextLabel(i);
            const Eigen::Vector3d ref[4] = {cc0, fc0, vec(p0[a]), vec(p0[b])};
            const Eigen::Vector3d cur[4] = {cc, fc, vec(p[a]), vec(p[b])};
            q = min(q, dcprbf::TetQuality::compute(ref, cur, metric_));
        }
    }
    return q;
}


Foam::scalarField Foam::dcpRBFCellQuality::compute
(
    const labelUList& cells,
    const pointField& p0,
    const pointField& p
) const
{
    // Addressing is built on first use: not thread-safe, so do it here
    mesh_.cells();
    scalarField q(cells.size());
    #pragma omp parallel for schedule(dynamic, 64)
    for (label i = 0; i < cells.size(); ++i)
    {
        q[i] = cellQuality(cells[i], p0, p);
    }
    return q;
}


// ************************************************************************* //
