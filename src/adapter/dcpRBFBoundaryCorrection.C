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

#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFBoundaryCorrection::dcpRBFBoundaryCorrection
(
    const dcprbf::Points& evalPoints,
    const dcpRBFBoundaryPoints& boundary,
    const scalar maxRadius
)
:
    nearest_(evalPoints.rows(), -1),
    distance_(evalPoints.rows(), GREAT),
    maxRadius_(maxRadius)
{
    if (boundary.size() == 0)
    {
        return;
    }
    const dcprbf::PointTree tree(boundary.points());

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < label(evalPoints.rows()); ++i)
    {
        if (boundary.kind(i) != dcpRBFBoundaryPoints::interiorPoint)
        {
            continue;
        }
        double d2 = 0;
        nearest_[i] = tree.nearest(evalPoints.row(i).data(), d2);
        distance_[i] = std::sqrt(d2);
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
    const scalar eMax = error.rows() ? error.rowwise().norm().maxCoeff() : 0;
    const scalar R = min(radiusFactor*eMax, maxRadius_);
    if (!(R > 0))
    {
        return 0;
    }
    const dcprbf::kernels::WendlandC2 phi{1.0/R};
    forAll(displacement, i)
    {
        if (nearest_[i] >= 0 && distance_[i] < R)
        {
            displacement[i] +=
                phi(distance_[i])*projection.fromCore(error.row(nearest_[i]).data());
        }
    }
    return R;
}


// ************************************************************************* //
