/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFCellQuality.H"
#include "dcpRBFPlanarCells.H"
#include "MortonOrder.hpp"
#include "TetQuality.hpp"

namespace
{
    //- A pointField as x y z per point (a vector is three contiguous scalars)
    const Foam::scalar* xyz(const Foam::pointField& p)
    {
        static_assert(sizeof(Foam::vector) == 3*sizeof(Foam::scalar), "packed vector");
        return reinterpret_cast<const Foam::scalar*>(p.cdata());
    }
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFCellQuality::dcpRBFCellQuality
(
    const polyMesh& mesh,
    dcprbf::TetQuality::Metric metric
)
:
    mesh_(mesh),
    metric_(metric),
    nCells_(0)
{}


Foam::dcpRBFCellQuality::dcpRBFCellQuality
(
    const polyMesh& mesh,
    const labelUList& cells,
    const pointField& points0,
    dcprbf::TetQuality::Metric metric
)
:
    mesh_(mesh),
    metric_(metric),
    nCells_(cells.size())
{
    dcpRBFPlanarCells sorted(mesh, cells, points0);
    if (sorted.planar().size())
    {
        planar_ = sorted.planar();
        planarScan_.reset
        (
            new dcprbf::PlanarCellQualityScan
            (
                std::move(sorted.polygonStart()), std::move(sorted.polygonPoints()),
                xyz(points0), sorted.axis0(), sorted.axis1(), metric
            )
        );
    }
    scanned_ = sorted.others();

    // The other cells' faces, each once, numbered in order of appearance
    // (a trial window's parts are copied from the region's scans
    // instead: dcpRBFCellQuality(from, positions, points0))
    const faceList& faces = mesh.faces();
    labelList compact(faces.size(), -1);
    std::vector<std::size_t> cellStart(1, 0), faceStart(1, 0);
    std::vector<int> cellFaces, facePoints;
    for (const label celli : labelUIndList(cells, scanned_))
    {
        for (const label facei : mesh.cells()[celli])
        {
            if (compact[facei] < 0)
            {
                compact[facei] = label(faceStart.size()) - 1;
                facePoints.insert(facePoints.end(), faces[facei].begin(), faces[facei].end());
                faceStart.push_back(facePoints.size());
            }
            cellFaces.push_back(compact[facei]);
        }
        cellStart.push_back(cellFaces.size());
    }
    scan_.reset
    (
        new dcprbf::CellQualityScan
        (
            std::move(cellStart), std::move(cellFaces), std::move(faceStart),
            std::move(facePoints), xyz(points0), metric
        )
    );
}


Foam::dcpRBFCellQuality::dcpRBFCellQuality
(
    const dcpRBFCellQuality& from,
    const labelUList& positions,
    const pointField& points0
)
:
    mesh_(from.mesh_),
    metric_(from.metric_),
    nCells_(positions.size())
{
    if (!from.subsettable() || points0.size() != mesh_.nPoints())
    {
        FatalErrorInFunction
            << "A subset of a cell quality constructed without cells, or"
            << " reference points not the mesh's (" << points0.size() << " for "
            << mesh_.nPoints() << " points)" << exit(FatalError);
    }
    if (from.scanOf_.size() != from.nCells_)
    {
        from.scanOf_.setSize(from.nCells_);
        forAll(from.planar_, k)
        {
            from.scanOf_[from.planar_[k]] = k;
        }
        forAll(from.scanned_, k)
        {
            from.scanOf_[from.scanned_[k]] = -1 - k;
        }
    }
    // each cell from the scan that measured it, at its place in the list
    std::vector<int> flat, polygons;
    flat.reserve(positions.size());
    DynamicList<label> scanned(positions.size()), planar;
    forAll(positions, i)
    {
        if (positions[i] < 0 || positions[i] >= from.nCells_)
        {
            FatalErrorInFunction
                << "Position " << positions[i] << " of a subset of "
                << from.nCells_ << " cells" << exit(FatalError);
        }
        const label k = from.scanOf_[positions[i]];
        if (k >= 0)
        {
            polygons.push_back(int(k));
            planar.append(i);
        }
        else
        {
            flat.push_back(int(-1 - k));
            scanned.append(i);
        }
    }
    scan_.reset(new dcprbf::CellQualityScan(*from.scan_, flat));
    scanned_.transfer(scanned);
    if (polygons.size())
    {
        planarScan_.reset
        (
            new dcprbf::PlanarCellQualityScan(*from.planarScan_, polygons, xyz(points0))
        );
        planar_.transfer(planar);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::dcpRBFCellQuality::cellsOfKind
(
    const dcprbf::CellQualityScan::Kind k
) const
{
    labelList positions;
    if (scan_.valid())
    {
        for (const int i : scan_->cellsOfKind(k))
        {
            positions.append(scanned_[i]);
        }
    }
    return positions;
}


Foam::scalarField Foam::dcpRBFCellQuality::compute(const pointField& p) const
{
    scalarField q;
    compute(p, q);
    return q;
}


void Foam::dcpRBFCellQuality::compute(const pointField& p, scalarField& q) const
{
    if (!scan_.valid())
    {
        FatalErrorInFunction
            << "No cells given at construction" << abort(FatalError);
    }
    q.setSize(nCells_);
    const auto measure = [&](const auto& scan, const labelList& positions)
    {
        if (positions.size() == q.size())
        {
            scan.measure(xyz(p), q.data());
        }
        else if (positions.size())
        {
            scalarField part(positions.size());
            scan.measure(xyz(p), part.data());
            UIndirectList<scalar>(q, positions) = part;
        }
    };
    measure(*scan_, scanned_);
    if (planarScan_.valid())
    {
        measure(*planarScan_, planar_);
    }
}


Foam::label Foam::dcpRBFCellQuality::computeLowest
(
    const pointField& p,
    scalarField& q,
    const label k
) const
{
    if (!scan_.valid() || planarScan_.valid() || scanned_.size() != nCells_)
    {
        // 2D (or mixed) cells: every cell measured
        compute(p, q);
        return nCells_;
    }
    q.setSize(nCells_);
    return label(scan_->measureLowest(xyz(p), q.data(), std::size_t(max(k, label(1)))));
}


Foam::labelList Foam::dcpRBFCellQuality::scanOrder
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


Foam::FixedList<Foam::scalar, 3> Foam::dcpRBFCellQuality::referenceCentre
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
