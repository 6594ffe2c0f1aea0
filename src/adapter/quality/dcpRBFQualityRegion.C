/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFQualityRegion.H"
#include "PointTree.hpp"
#include "Pstream.H"
#include "emptyPolyPatch.H"
#include "processorPolyPatch.H"
#include "dcpRBFVersion.H"

#include <algorithm>
#include <limits>

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

dcprbf::Points Foam::dcpRBFQualityRegion::checkSources
(
    const polyMesh& mesh,
    const dcpRBFPlaneProjection& projection,
    const pointField& points0,
    const dcpRBFBoundaryPoints& boundaryPoints
)
{
    // This processor's points of the other patches (not candidates)
    std::vector<char> mark(std::size_t(mesh.nPoints()), false);
    DynamicList<FixedList<scalar, 3>> local;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<emptyPolyPatch>(pp) || isA<processorPolyPatch>(pp))
        {
            continue;
        }
        for (const label pointi : pp.meshPoints())
        {
            if
            (
                !mark[pointi]
             && boundaryPoints.kind(pointi) == dcpRBFBoundaryPoints::interiorPoint
            )
            {
                mark[pointi] = true;
                FixedList<scalar, 3> x;
                projection.toCore(points0[pointi], x.data());
                local.append(x);
            }
        }
    }
    const List<List<FixedList<scalar, 3>>> all
    (
        dcpRBFCompat::allGather<FixedList<scalar, 3>>(local)
    );

    const dcprbf::Points& candidates = boundaryPoints.points();
    label n = candidates.rows();
    for (const auto& l : all) n += l.size();
    dcprbf::Points sources(n, 3);
    sources.topRows(candidates.rows()) = candidates;
    label row = candidates.rows();
    for (const auto& l : all)
    {
        for (const auto& x : l)
        {
            sources.row(row++) << x[0], x[1], x[2];
        }
    }
    return sources;
}


Foam::dcpRBFRankedCell Foam::dcpRBFQualityRegion::globalLowest
(
    const dcpRBFRankedCell& local
)
{
    // Gathered as lists of scalars: newer versions gather a list of
    // FixedLists (contiguous) with memmove, a -Wclass-memaccess warning; and
    // reduce of a FixedList is elementwise, not the lexicographic order here
    const List<scalarList> all
    (
        dcpRBFCompat::allGather(dcpRBFCompat::makeList<scalar>(local))
    );
    dcpRBFRankedCell lowest(local);
    for (const scalarList& c : all)
    {
        lowest = std::min(lowest, dcpRBFRankedCell(c));
    }
    return lowest;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFQualityRegion::dcpRBFQualityRegion
(
    const polyMesh& mesh,
    const dcpRBFPlaneProjection& projection,
    const pointField& points0,
    const dcprbf::Points& movingPoints,
    const dcprbf::Points& sources,
    const scalar radius,
    const bool affineBeyond,
    const dcprbf::TetQuality::Metric metric,
    const scalar movingReach,
    const dcpRBFRegion* region
)
{
    // The cells whose reference centre (the average of their points) is
    // within radius of a moving point: found in parallel (the search
    // stops at the first point within reach)
    const labelListList& cellPoints = mesh.cellPoints();
    std::vector<char> inside(std::size_t(mesh.nCells()), false);
    if (movingPoints.rows() > 0)
    {
        const dcprbf::PointTree tree(movingPoints);
        #pragma omp parallel for schedule(dynamic, 4096)
        for (label celli = 0; celli < mesh.nCells(); ++celli)
        {
            inside[celli] =
                (!region || region->cell(celli))
             && tree.anyWithin
                (
                    dcpRBFCellQuality::referenceCentre(cellPoints, projection, points0, celli).data(), radius
                );
        }
    }
    std::vector<label> found;
    for (label celli = 0; celli < mesh.nCells(); ++celli)
    {
        if (inside[celli]) found.push_back(celli);
    }
    cells_ = dcpRBFCellQuality::scanOrder(mesh, points0, found);
    centres_.setSize(cells_.size());
    forAll(cells_, i)
    {
        centres_[i] = dcpRBFCellQuality::referenceCentre(cellPoints, projection, points0, cells_[i]);
    }
    quality_.reset(new dcpRBFCellQuality(mesh, cells_, points0, metric));

    // the others checked: neither the region's nor outside the cells dcpRBF
    // moves
    std::vector<char> skip(inside);
    if (region)
    {
        for (label celli = 0; celli < mesh.nCells(); ++celli)
        {
            skip[celli] = skip[celli] || !region->cell(celli);
        }
    }
    outer_.reset
    (
        new dcpRBFOuterCells
        (
            mesh, projection, points0, sources, radius, affineBeyond, skip,
            metric, movingPoints, movingReach
        )
    );
    nChecked_ = returnReduce(cells_.size() + outer_->nChecked(), sumOp<label>());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFQualityRegion::size() const
{
    return returnReduce(cells_.size(), sumOp<label>());
}


Foam::scalarField Foam::dcpRBFQualityRegion::quality(const pointField& p) const
{
    return quality_->compute(p);
}


Foam::labelList Foam::dcpRBFQualityRegion::within
(
    const Eigen::RowVector3d& x,
    const scalar radius
) const
{
    // the centres are a flat array of 3 scalars each, in Morton order
    static_assert
    (
        sizeof(FixedList<scalar, 3>) == 3*sizeof(scalar),
        "centres as a flat array"
    );
    if (!index_)
    {
        index_.reset
        (
            new dcprbf::BlockBoxIndex
            (
                reinterpret_cast<const scalar*>(centres_.cdata()),
                std::size_t(centres_.size())
            )
        );
    }
    // found in ascending positions
    DynamicList<label> positions;
    index_->forEachWithin
    (
        x.data(), radius,
        [&](std::size_t i, double) { positions.append(label(i)); }
    );
    return labelList(std::move(positions));
}


// ************************************************************************* //
