/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFOuterCells.H"
#include "PointTree.hpp"

#include <memory>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFOuterCells::dcpRBFOuterCells
(
    const polyMesh& mesh,
    const dcpRBFPlaneProjection& projection,
    const pointField& points0,
    const dcprbf::Points& sources,
    const scalar radius,
    const bool affineBeyond,
    const std::vector<char>& skip,
    const dcprbf::TetQuality::Metric metric,
    const dcprbf::Points& moving,
    const scalar movingReach
)
{
    // Per point: can a kernel, a condition or a correction move it other
    // than by the polynomial? (every point where that is not known)
    std::vector<char> near(std::size_t(mesh.nPoints()), !affineBeyond);
    if (affineBeyond && sources.rows() > 0)
    {
        const dcprbf::PointTree tree(sources);
        const bool farther = movingReach > radius && moving.rows() > 0;
        std::unique_ptr<dcprbf::PointTree> movingTree;
        if (farther)
        {
            movingTree.reset(new dcprbf::PointTree(moving));
        }
        #pragma omp parallel for schedule(dynamic, 4096)
        for (label pointi = 0; pointi < mesh.nPoints(); ++pointi)
        {
            FixedList<scalar, 3> x;
            projection.toCore(points0[pointi], x.data());
            near[pointi] =
                tree.anyWithin(x.data(), radius)
             || (farther && movingTree->anyWithin(x.data(), movingReach));
        }
    }
    const labelListList& cellPoints = mesh.cellPoints();
    std::vector<label> outer;
    label firstAffine = -1;
    for (label celli = 0; celli < mesh.nCells(); ++celli)
    {
        if (skip[celli])
        {
            continue;
        }
        bool moves = false;
        for (const label pi : cellPoints[celli])
        {
            if (near[pi])
            {
                moves = true;
                break;
            }
        }
        if (moves)
        {
            outer.push_back(celli);
        }
        else
        {
            if (firstAffine < 0) firstAffine = celli;
            ++nAffine_;
        }
    }
    cells_ = dcpRBFCellQuality::scanOrder(mesh, points0, outer);
    if (nAffine_ > 0)
    {
        // last: the cell that stands for the nAffine_ moved affinely
        cells_.append(firstAffine);
    }
    centres_.setSize(cells_.size());
    forAll(cells_, i)
    {
        centres_[i] =
            dcpRBFCellQuality::referenceCentre(cellPoints, projection, points0, cells_[i]);
    }
    quality_.reset(new dcpRBFCellQuality(mesh, cells_, points0, metric));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFOuterCells::accumulate
(
    const pointField& p,
    label& nInverted,
    scalar& sum,
    dcpRBFRankedCell& lowest
) const
{
    const scalarField q(quality_->compute(p));
    forAll(q, i)
    {
        const label weight = (nAffine_ > 0 && i == q.size() - 1) ? nAffine_ : 1;
        nInverted += weight*(q[i] <= 0);
        sum += weight*q[i];
        const dcpRBFRankedCell c(q[i], centres_[i]);
        if (c < lowest) lowest = c;
    }
}


// ************************************************************************* //
