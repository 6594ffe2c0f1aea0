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
    const dcpRBFContext& context,
    const dcpRBFControlPoints& controlPoints,
    const dcpRBFRotation& rotation,
    dcpRBFPrescribedDisplacement& prescribed
)
:
    settings_(context.settings()),
    projection_(context.projection()),
    boundaryPoints_(context.boundaryPoints()),
    distinct_(context.distinct()),
    controlPoints_(controlPoints),
    rotation_(rotation),
    prescribed_(prescribed),
    stepMesh_(context.stepMesh()),
    stored_
    (
        settings_.kernel(), controlPoints.evaluator().polynomial(),
        distinct_.points()
    ),
    correction_
    (
        context.evalPoints(), boundaryPoints_, controlPoints.block().blocks(),
        settings_.kernel().radius()
    ),
    farField_(context)
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
    if (!controlPoints_.ready())
    {
        withoutSet();
        return 0;
    }
    // evaluated once per distinct point (2D: the front and back twins)
    const dcprbf::RbfEvaluator& s = controlPoints_.evaluator();
    const std::size_t budget = controlPoints_.storageBudget();
    const bool stored = stored_.prepare(s.centres(), budget);
    vectorField& disp = stepMesh_.change().primitiveFieldRef();
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
    vectorField& disp = stepMesh_.change().primitiveFieldRef();
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
    farField_.apply(disp);
    prescribed_.constrainInterpolated();

    scalar err = 0;
    for (label i = 0; i < label(error.rows()); ++i)
    {
        if (boundaryPoints_.moving()[b0 + i]) err = max(err, error.row(i).norm());
    }
    reduce(err, maxOp<scalar>());
    return dcprbf::relativeToLargest(err, d, settings_.kernel().radius());
}


void Foam::dcpRBFInterpolation::withoutSet()
{
    vectorField& disp = stepMesh_.change().primitiveFieldRef();
    if (!rotation_.active())
    {
        // nothing moves yet: every point but the moving ones stays put,
        // unless a patch in neither list is moved by its own condition
        disp = prescribed_.values();
        if (prescribed_.selfMoved().size())
        {
            prescribed_.constrain();
        }
        return;
    }
    // Rigid bodies: the blended rigid motions alone
    forAll(disp, pointi)
    {
        disp[pointi] =
            boundaryPoints_.kind(pointi) == dcpRBFBoundaryPoints::interiorPoint
          ? projection_.fromCore(rotation_.displacement().row(pointi).data())
          : prescribed_.values()[pointi];
    }
    prescribed_.constrainInterpolated();
}


bool Foam::dcpRBFInterpolation::evaluateRows
(
    const std::vector<int>& rows,
    vectorField& field,
    dcprbf::Values& scratch
)
{
    // the set's values at those rows as the stored matrix would give them
    // (without a patch over every point if the current matrix serves the
    // set with a few columns more), else the set's matrix prepared, else
    // (not stored) as the evaluation on the fly of every point would
    const dcprbf::RbfEvaluator& s = controlPoints_.evaluator();
    const std::size_t budget = controlPoints_.storageBudget();
    const label dim = projection_.dim();
    double* out = &field[0][0];
    if
    (
        stored_.evaluateRowsFor
        (
            s.centres(), budget, s.weights(), s.polynomialCoeffs(),
            interiorTargets_, dim, out, rows
        )
    )
    {
        return true;
    }
    if (stored_.prepare(s.centres(), budget))
    {
        return stored_.evaluateInto
        (
            s.weights(), s.polynomialCoeffs(), interiorTargets_, dim, out,
            &rows
        );
    }
    // to the rows' points as the stored product writes them
    const dcprbf::Points& x = distinct_.points();
    scratch.resize(rows.size(), 3);
    s.evaluateRows(x.data(), x.rows(), rows, scratch.data());
    for (std::size_t k = 0; k < rows.size(); ++k)
    {
        interiorTargets_.write(rows[k], scratch.row(k).data(), dim, out);
    }
    return true;
}


Foam::scalar Foam::dcpRBFInterpolation::correct
(
    const dcprbf::Values& d,
    vectorField& field
)
{
    const dcpRBFStepMesh::loan inPlace(stepMesh_, field);
    return correct(d);
}


// ************************************************************************* //
