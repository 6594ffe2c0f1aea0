/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFFarField.H"
#include "PointTree.hpp"

#include <cmath>

// * * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * //

Foam::scalar Foam::dcpRBFFarField::weight
(
    const scalar r,
    const scalar inner,
    const scalar outer
)
{
    if (r <= inner)
    {
        return 1;
    }
    if (r >= outer)
    {
        return 0;
    }
    const scalar t = (r - inner)/(outer - inner);
    return 1 - t*t*t*(10 - 15*t + 6*t*t);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFFarField::dcpRBFFarField(const dcpRBFContext& context)
{
    const dcpRBFSettings& settings = context.settings();
    const dcprbf::Points moving(context.boundaryPoints().movingPoints());
    if (!settings.stillFarField() || moving.rows() == 0)
    {
        return;
    }
    const scalar inner = settings.farFieldRadii().first;
    const scalar outer = settings.farFieldRadii().second;
    const dcprbf::Points& x = context.evalPoints();
    const dcpRBFBoundaryPoints& boundary = context.boundaryPoints();
    const label n = x.rows();
    scalarField w(n, 1);
    const dcprbf::PointTree tree(moving);
    #pragma omp parallel for schedule(dynamic, 4096)
    for (label pointi = 0; pointi < n; ++pointi)
    {
        if (boundary.kind(pointi) == dcpRBFBoundaryPoints::interiorPoint)
        {
            double d2 = 0;
            tree.nearest(x.row(pointi).data(), d2);
            w[pointi] = weight(std::sqrt(d2), inner, outer);
        }
    }
    DynamicList<label> points;
    DynamicList<scalar> weights;
    forAll(w, pointi)
    {
        if (w[pointi] < 1)
        {
            points.append(pointi);
            weights.append(w[pointi]);
        }
    }
    points_.transfer(points);
    weights_.transfer(weights);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFFarField::apply(vectorField& displacement) const
{
    forAll(points_, i)
    {
        displacement[points_[i]] *= weights_[i];
    }
}


// ************************************************************************* //
