/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFBoundaryCorrection.H"
#include "PointTree.hpp"
#include "RadialKernel.hpp"
#include "DynamicList.H"
#include "UIndirectList.H"
#include "PstreamReduceOps.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::boolList Foam::dcpRBFBoundaryCorrection::interiorMask
(
    const dcpRBFBoundaryPoints& boundary
)
{
    boolList interior(boundary.kinds().size());
    forAll(interior, pointi)
    {
        interior[pointi] = boundary.kind(pointi) == dcpRBFBoundaryPoints::interiorPoint;
    }
    return interior;
}


void Foam::dcpRBFBoundaryCorrection::fetchFrom
(
    const globalIndex& sources,
    const labelList& sourceOf
)
{
    if (sourceOf.size())
    {
        forAll(nearest_, k)
        {
            nearest_[k] = sourceOf[nearest_[k]];
        }
    }
    // this processor's sources first, then the others' it needs, each once
    List<Map<label>> compactMap;
    halo_.reset(new mapDistribute(sources, nearest_, compactMap));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFBoundaryCorrection::dcpRBFBoundaryCorrection
(
    const dcprbf::Points& evalPoints,
    const dcpRBFBoundaryPoints& boundary,
    const globalIndex& blocks,
    const scalar maxRadius
)
:
    dcpRBFBoundaryCorrection
    (
        evalPoints, boundary.points(), interiorMask(boundary), maxRadius
    )
{
    fetchFrom(blocks, labelList());
}


Foam::dcpRBFBoundaryCorrection::dcpRBFBoundaryCorrection
(
    const dcprbf::Points& evalPoints,
    const dcpRBFBoundaryPoints& targets,
    const boolList& corrected,
    const scalar maxRadius,
    const scalarField& targetRadius
)
:
    dcpRBFBoundaryCorrection
    (
        evalPoints, targets.points(), corrected, maxRadius, targetRadius
    )
{
    fetchFrom(targets.holders(), targets.holderOf());
}


Foam::dcpRBFBoundaryCorrection::dcpRBFBoundaryCorrection
(
    const dcprbf::Points& evalPoints,
    const dcprbf::Points& targets,
    const boolList& corrected,
    const scalar maxRadius,
    const scalarField& targetRadius
)
:
    maxRadius_(maxRadius)
{
    if (targets.rows() == 0)
    {
        return;
    }
    const dcprbf::PointTree tree(targets);
    const label n = label(evalPoints.rows());
    labelList nearest(n, -1);
    scalarField distance(n, GREAT);

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        if (!corrected[i])
        {
            continue;
        }
        double d2 = 0;
        nearest[i] = tree.nearest(evalPoints.row(i).data(), d2);
        distance[i] = std::sqrt(d2);
    }

    // ascending distance (ties by point: the same order on any thread count)
    DynamicList<label> interior(n);
    for (label i = 0; i < n; ++i)
    {
        // (beyond maxRadius no blend reaches: not kept)
        if (nearest[i] >= 0 && distance[i] < maxRadius) interior.append(i);
    }
    std::sort
    (
        interior.begin(), interior.end(),
        [&](const label a, const label b)
        {
            return distance[a] < distance[b] || (distance[a] == distance[b] && a < b);
        }
    );
    point_.transfer(interior);
    nearest_ = labelList(UIndirectList<label>(nearest, point_));
    distance_ = scalarField(UIndirectList<scalar>(distance, point_));
    if (targetRadius.size())
    {
        radius_ = scalarField(UIndirectList<scalar>(targetRadius, nearest_));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dcpRBFBoundaryCorrection::apply
(
    const dcprbf::Values& error,
    const dcpRBFPlaneProjection& projection,
    vectorField& displacement
) const
{
    scalar eMax = error.rows() ? error.rowwise().norm().maxCoeff() : 0;
    if (halo_)
    {
        reduce(eMax, maxOp<scalar>());
    }
    const scalar R = min(radiusFactor*eMax, maxRadius_);
    if (!(R > 0))
    {
        return 0;
    }
    // the errors in the mesh's axes, once per target (with the halo: the
    // others' after the block's, on every processor)
    vectorField errorOnMesh(label(error.rows()));
    forAll(errorOnMesh, b)
    {
        errorOnMesh[b] = projection.fromCore(error.row(b).data());
    }
    if (halo_)
    {
        halo_->distribute(errorOnMesh);
    }
    const dcprbf::kernels::WendlandC2 phi{1.0/R};
    // the points within R (ascending distance); each point once: threads
    // for many
    const label kEnd =
        label(std::lower_bound(distance_.begin(), distance_.end(), R) - distance_.begin());
    if (kEnd == 0)
    {
        return R;
    }
    const label* point = point_.cdata();
    const label* nearest = nearest_.cdata();
    const scalar* distance = distance_.cdata();
    const vector* e = errorOnMesh.cdata();
    vector* d = displacement.data();
    if (radius_.empty())
    {
        #pragma omp parallel for schedule(static) if(kEnd >= minParallelPoints)
        for (label k = 0; k < kEnd; ++k)
        {
            d[point[k]] += phi(distance[k])*e[nearest[k]];
        }
        return R;
    }
    #pragma omp parallel for schedule(static) if(kEnd >= minParallelPoints)
    for (label k = 0; k < kEnd; ++k)
    {
        const scalar weight =
            radius_[k] >= R
          ? phi(distance[k])
          : distance[k] < radius_[k]
          ? dcprbf::kernels::WendlandC2{1.0/radius_[k]}(distance[k])
          : 0;
        d[point[k]] += weight*e[nearest[k]];
    }
    return R;
}


// ************************************************************************* //
