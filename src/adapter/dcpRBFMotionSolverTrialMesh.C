/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFMotionSolver, continued: a trial swap's mesh made at some points
    alone, the same values there as the whole mesh's.
\*---------------------------------------------------------------------------*/

#include "dcpRBFMotionSolver.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dcpRBFMotionSolver::interpolateAt
(
    const dcprbf::Values& d,
    const labelUList& points,
    scalar& error
)
{
    // Restricted where every step of interpolateDisplacement() is either
    // the point's own (the product's row, the prescribed value, the
    // boundary correction, the 2D pair) or reads finishedPoints_ alone (the
    // patches' conditions and constraints, the sliding walls' change and
    // its blend, the processors' synchronisation): those are made too.
    // Restricted on every processor or on none (the constraints exchange
    // values)
    const dcprbf::RbfEvaluator& s = controlPoints_.evaluator();
    if
    (
        rotation_.active()
     || projection_.axis(0) != 0 || projection_.axis(1) != 1 || projection_.axis(2) != 2
     || !returnReduce(pointDisplacement_.size() > 0, andOp<bool>())
    )
    {
        return false;
    }
    // the distinct rows of the interior points among them, ascending
    const dcpRBFBoundaryPoints::pointKind* kind = boundaryPoints_.kinds().cdata();
    rowMarks_.resize(distinct_.points().rows(), 0);
    trialRows_.clear();
    const auto addRows = [&](const labelUList& pts)
    {
        for (const label pointi : pts)
        {
            if (kind[pointi] == dcpRBFBoundaryPoints::interiorPoint)
            {
                const label row = distinct_.of(pointi);
                if (!rowMarks_[row])
                {
                    rowMarks_[row] = 1;
                    trialRows_.push_back(int(row));
                }
            }
        }
    };
    addRows(points);
    addRows(finishedPoints_);
    for (const int row : trialRows_)
    {
        rowMarks_[row] = 0;
    }
    std::sort(trialRows_.begin(), trialRows_.end());

    // (the trial's field starts as the displacement of its first use:
    // every value finite where it is not made, never read there)
    vectorField& disp = pointDisplacement_.primitiveFieldRef();
    if (trialDisplacement_.size() != disp.size())
    {
        trialDisplacement_ = disp;
    }
    // the set's values at those rows as the stored matrix would give them
    // (without a patch over every point if the current matrix serves the
    // set with a few columns more), else the set's matrix prepared, else
    // (not stored) as the evaluation on the fly of every point would
    const std::size_t budget = std::size_t(settings_.evaluationMemoryMB()) << 20;
    const label dim = projection_.dim();
    double* out = &trialDisplacement_[0][0];
    bool made =
        stored_.evaluateRowsFor
        (
            s.centres(), budget, s.weights(), s.polynomialCoeffs(),
            interiorTargets_, dim, out, trialRows_
        );
    if (!made && stored_.prepare(s.centres(), budget))
    {
        made = stored_.evaluateInto
        (
            s.weights(), s.polynomialCoeffs(), interiorTargets_, dim, out,
            &trialRows_
        );
    }
    else if (!made)
    {
        // as copyValues() writes them
        const dcprbf::Points& x = distinct_.points();
        trialValues_.resize(trialRows_.size(), 3);
        s.evaluateRows(x.data(), x.rows(), trialRows_, trialValues_.data());
        const dcprbf::StoredEvaluation::Targets& t = interiorTargets_;
        for (std::size_t k = 0; k < trialRows_.size(); ++k)
        {
            const std::size_t row = trialRows_[k];
            for (std::size_t e = t.start[row]; e < t.start[row + 1]; ++e)
            {
                vector& o = trialDisplacement_[t.point[e]];
                o[0] = trialValues_(k, 0);
                o[1] = trialValues_(k, 1);
                o[2] = dim == 3 ? trialValues_(k, 2) : 0.0;
            }
        }
        made = true;
    }
    if (!returnReduce(made, andOp<bool>()))
    {
        return false;
    }
    for (const label pointi : boundaryMeshPoints_)
    {
        trialDisplacement_[pointi] = prescribed_[pointi];
    }

    // the correction and the constraints on the trial's field, in place of
    // the displacement's (exchanged, not copied)
    disp.swap(trialDisplacement_);
    error = correctInterpolated(d);
    disp.swap(trialDisplacement_);

    // the points: 2D pairs over the whole field, else each point alone
    if (twoDPoints_.required())
    {
        twoDPoints_.move(points0(), trialDisplacement_, trialPoints_);
    }
    else
    {
        trialPoints_.setSize(disp.size());
        const pointField& p0 = points0();
        for (const label pointi : points)
        {
            trialPoints_[pointi] = p0[pointi] + trialDisplacement_[pointi];
        }
    }
    return true;
}


// ************************************************************************* //
