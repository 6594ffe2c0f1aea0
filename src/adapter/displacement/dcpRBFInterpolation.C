/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFInterpolation.H"
#include "PstreamReduceOps.H"

#include <numeric>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFInterpolation::dcpRBFInterpolation
(
    const dcpRBFSettings& settings,
    const dcpRBFPlaneProjection& projection,
    const dcpRBFBoundaryPoints& boundaryPoints,
    const dcprbf::Points& evalPoints,
    const dcprbf::DistinctRows& distinct,
    const dcpRBFControlPoints& controlPoints,
    const dcpRBFRotation& rotation,
    const dcpRBFTwoDPoints& twoDPoints,
    dcpRBFPrescribedDisplacement& prescribed,
    pointVectorField& pointDisplacement,
    const pointField& points0
)
:
    settings_(settings),
    projection_(projection),
    boundaryPoints_(boundaryPoints),
    distinct_(distinct),
    controlPoints_(controlPoints),
    rotation_(rotation),
    twoDPoints_(twoDPoints),
    prescribed_(prescribed),
    pointDisplacement_(pointDisplacement),
    points0_(points0),
    stored_
    (
        settings.kernel(), controlPoints.evaluator().polynomial(),
        distinct.points()
    ),
    correction_
    (
        evalPoints, boundaryPoints, controlPoints.block().blocks(),
        settings.kernel().radius()
    )
{
    // Each distinct reference point's interior points
    {
        const dcpRBFBoundaryPoints::pointKind* kind = boundaryPoints_.kinds().cdata();
        std::vector<std::size_t>& start = interiorTargets_.start;
        start.assign(std::size_t(distinct_.points().rows()) + 1, 0);
        for (label pointi = 0; pointi < boundaryPoints_.kinds().size(); ++pointi)
        {
            if (kind[pointi] == dcpRBFBoundaryPoints::interiorPoint)
            {
                ++start[std::size_t(distinct_.of(pointi)) + 1];
            }
        }
        std::partial_sum(start.begin(), start.end(), start.begin());
        std::vector<std::size_t> next(start.begin(), start.end() - 1);
        interiorTargets_.point.resize(start.back());
        for (label pointi = 0; pointi < boundaryPoints_.kinds().size(); ++pointi)
        {
            if (kind[pointi] == dcpRBFBoundaryPoints::interiorPoint)
            {
                interiorTargets_.point[next[std::size_t(distinct_.of(pointi))]++] = int(pointi);
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dcpRBFInterpolation::writesRowsToPoints() const
{
    return
        !rotation_.active()
     && projection_.axis(0) == 0 && projection_.axis(1) == 1 && projection_.axis(2) == 2;
}


void Foam::dcpRBFInterpolation::copyValues
(
    const dcprbf::Values& v,
    vectorField& disp
) const
{
    if (rotation_.active())
    {
        forAll(disp, pointi)
        {
            if (boundaryPoints_.kind(pointi) != dcpRBFBoundaryPoints::interiorPoint)
            {
                disp[pointi] = prescribed_.values()[pointi];
            }
            else
            {
                const Eigen::RowVector3d u
                (
                    v.row(distinct_.of(pointi)) + rotation_.displacement().row(pointi)
                );
                disp[pointi] = projection_.fromCore(u.data());
            }
        }
    }
    else
    {
        // projection_.fromCore in one loop: the axes in locals (not
        // reloaded after each store, as the compiler must for char members)
        const label a0 = projection_.axis(0), a1 = projection_.axis(1), a2 = projection_.axis(2);
        const bool threeD = projection_.dim() == 3;
        const dcpRBFBoundaryPoints::pointKind* kind = boundaryPoints_.kinds().cdata();
        const point* prescribed = prescribed_.values().cdata();
        vector* out = disp.data();
        const label n = disp.size();
        for (label pointi = 0; pointi < n; ++pointi)
        {
            if (kind[pointi] != dcpRBFBoundaryPoints::interiorPoint)
            {
                out[pointi] = prescribed[pointi];
            }
            else
            {
                const double* c = &v(distinct_.of(pointi), 0);
                vector& o = out[pointi];
                o[a0] = c[0];
                o[a1] = c[1];
                o[a2] = threeD ? c[2] : 0.0;
            }
        }
    }
}


Foam::scalar Foam::dcpRBFInterpolation::interpolate
(
    const dcprbf::Values& d
)
{
    // evaluated once per distinct point (2D: the front and back twins)
    const dcprbf::RbfEvaluator& s = controlPoints_.evaluator();
    const std::size_t budget = controlPoints_.storageBudget();
    const bool stored = stored_.prepare(s.centres(), budget);
    vectorField& disp = pointDisplacement_.primitiveFieldRef();
    if
    (
        stored && writesRowsToPoints() && disp.size()
     && stored_.evaluateInto
        (
            s.weights(), s.polynomialCoeffs(), interiorTargets_, projection_.dim(),
            &disp[0][0]
        )
    )
    {
        // the control set's matrix is stored (patched or not), the core's
        // axes are the mesh's: one product written straight to the
        // interior points (in 2D to both twins of a distinct point), then
        // the prescribed
        prescribed_.insert(disp);
    }
    else
    {
        const dcprbf::Points& x = distinct_.points();
        dcprbf::Values& v = values_;
        v.resize(x.rows(), 3);
        if (stored)
        {
            // the control set's matrix is stored: one product
            stored_.evaluate(s.weights(), s.polynomialCoeffs(), v);
        }
        else
        {
            s.evaluate(x.data(), x.rows(), v.data());
        }
        copyValues(v, disp);
    }
    return correct(d);
}


Foam::scalar Foam::dcpRBFInterpolation::correct
(
    const dcprbf::Values& d
)
{
    // Error at this processor's block of the boundary points, blended
    // into the volume (the correction fetches the errors its points need)
    vectorField& disp = pointDisplacement_.primitiveFieldRef();
    const label b0 = controlPoints_.block().begin();
    const dcprbf::Values error
    (
        d.middleRows(b0, controlPoints_.block().end() - b0)
      - controlPoints_.blockValues()
    );
    if (settings_.boundaryCorrection())
    {
        correction_.apply(error, projection_, disp);
    }
    prescribed_.constrainInterpolated();

    scalar err = 0;
    for (label i = 0; i < label(error.rows()); ++i)
    {
        if (boundaryPoints_.moving()[b0 + i]) err = max(err, error.row(i).norm());
    }
    reduce(err, maxOp<scalar>());
    const scalar dMax = d.rows() ? d.rowwise().norm().maxCoeff() : 0;
    return dMax > 0 ? err/dMax : 0;
}


void Foam::dcpRBFInterpolation::rigid()
{
    // Rigid bodies: the blended rigid motions alone
    vectorField& disp = pointDisplacement_.primitiveFieldRef();
    forAll(disp, pointi)
    {
        disp[pointi] =
            boundaryPoints_.kind(pointi) == dcpRBFBoundaryPoints::interiorPoint
          ? projection_.fromCore(rotation_.displacement().row(pointi).data())
          : prescribed_.values()[pointi];
    }
    prescribed_.constrainInterpolated();
}


// ************************************************************************* //
