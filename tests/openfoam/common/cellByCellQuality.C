/*---------------------------------------------------------------------------*\
  dcpRBF tests
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "cellByCellQuality.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The plain averages of the points of the faces of these cells
std::vector<Eigen::Vector3d> faceCentres
(
    const polyMesh& mesh_,
    const labelUList& cells,
    const pointField& p
)
{
    const faceList& faces = mesh_.faces();
    std::vector<char> needed(faces.size(), 0);
    for (const label celli : cells)
    {
        for (const label facei : mesh_.cells()[celli]) needed[facei] = 1;
    }
    std::vector<Eigen::Vector3d> fc(faces.size(), Eigen::Vector3d::Zero());
    #pragma omp parallel for schedule(static)
    for (label facei = 0; facei < faces.size(); ++facei)
    {
        if (!needed[facei]) continue;
        Eigen::Vector3d s(Eigen::Vector3d::Zero());
        for (const label pi : faces[facei]) s += Eigen::Vector3d(p[pi].x(), p[pi].y(), p[pi].z());
        fc[facei] = s/faces[facei].size();
    }
    return fc;
}


scalar cellQuality
(
    const polyMesh& mesh_,
    const dcprbf::TetQuality::Metric metric_,
    const label celli,
    const pointField& p0,
    const pointField& p,
    const std::vector<Eigen::Vector3d>& fc0,
    const std::vector<Eigen::Vector3d>& fc
)
{
    const cell& c = mesh_.cells()[celli];
    const faceList& faces = mesh_.faces();

    // Cell centres as plain averages of the face centres (the same
    // construction for both meshes)
    Eigen::Vector3d cc0(Eigen::Vector3d::Zero()), cc(Eigen::Vector3d::Zero());
    for (const label facei : c)
    {
        cc0 += fc0[facei];
        cc += fc[facei];
    }
    cc0 /= c.size();
    cc /= c.size();
    const auto vec = [](const point& x) { return Eigen::Vector3d(x.x(), x.y(), x.z()); };
    scalar q = GREAT;
    for (const label facei : c)
    {
        const face& f = faces[facei];
        forAll(f, i)
        {
            const label a = f[i], b = f.nextLabel(i);
            const Eigen::Vector3d ref[4] = {cc0, fc0[facei], vec(p0[a]), vec(p0[b])};
            const Eigen::Vector3d cur[4] = {cc, fc[facei], vec(p[a]), vec(p[b])};
            q = min(q, dcprbf::TetQuality::compute(ref, cur, metric_));
        }
    }
    return q;
}

} // namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalarField Foam::cellByCellQuality
(
    const polyMesh& mesh_,
    const labelUList& cells,
    const pointField& p0,
    const pointField& p,
    const dcprbf::TetQuality::Metric metric
)
{
    // Addressing is built on first use: not thread-safe, so do it here
    mesh_.cells();
    const std::vector<Eigen::Vector3d> fc0(faceCentres(mesh_, cells, p0));
    const std::vector<Eigen::Vector3d> fc(faceCentres(mesh_, cells, p));
    scalarField q(cells.size());
    #pragma omp parallel for schedule(dynamic, 64)
    for (label i = 0; i < cells.size(); ++i)
    {
        q[i] = cellQuality(mesh_, metric, cells[i], p0, p, fc0, fc);
    }
    return q;
}


// ************************************************************************* //
