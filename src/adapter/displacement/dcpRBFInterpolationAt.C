/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFInterpolation, continued: a trial swap's mesh made at some points
    alone, the same values there as the whole mesh's.
\*---------------------------------------------------------------------------*/

#include "dcpRBFInterpolation.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dcpRBFInterpolation::interpolateAt
(
    const dcprbf::Values& d,
    const labelUList& points,
    scalar& error
)
{
    // Restricted where every step of interpolate() is either
    // the point's own (the product's row, the prescribed value, the
    // boundary correction, the 2D pair) or reads the finished points alone (the
    // patches' conditions and constraints, the sliding walls' change and
    // its blend, the processors' synchronisation): those are made too.
    // Restricted on every processor or on none (the constraints exchange
    // values)
    const dcprbf::RbfEvaluator& s = controlPoints_.evaluator();
    if
    (
        !writesRowsToPoints()
     || !returnReduce(pointDisplacement_.size() > 0, andOp<bool>())
    )
    {
        return false;
    }
    // the distinct rows of the interior points among them and of
    // the finished points (those once, at the first trial: marked 1 for good),
    // ascending
    const dcpRBFBoundaryPoints::pointKind* kind = boundaryPoints_.kinds().cdata();
    const auto addRows = [&](const labelUList& pts, const char mark)
    {
        for (const label pointi : pts)
        {
            if (kind[pointi] == dcpRBFBoundaryPoints::interiorPoint)
            {
                const label row = distinct_.of(pointi);
                if (!rowMarks_[row])
                {
                    rowMarks_[row] = mark;
                    trialRows_.push_back(int(row));
                }
            }
        }
        std::sort(trialRows_.begin(), trialRows_.end());
    };
    if (rowMarks_.empty())
    {
        rowMarks_.resize(distinct_.points().rows(), 0);
        trialRows_.clear();
        addRows(prescribed_.finishedPoints(), 1);
        finishedRows_ = trialRows_;
    }
    trialRows_.clear();
    addRows(points, 2);
    for (const int row : trialRows_)
    {
        rowMarks_[row] = 0;
    }
    const std::ptrdiff_t nWindow = trialRows_.size();
    trialRows_.insert(trialRows_.end(), finishedRows_.begin(), finishedRows_.end());
    std::inplace_merge(trialRows_.begin(), trialRows_.begin() + nWindow, trialRows_.end());

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
    const std::size_t budget = controlPoints_.storageBudget();
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
        // to the rows' points as the stored product writes them
        const dcprbf::Points& x = distinct_.points();
        trialValues_.resize(trialRows_.size(), 3);
        s.evaluateRows(x.data(), x.rows(), trialRows_, trialValues_.data());
        for (std::size_t k = 0; k < trialRows_.size(); ++k)
        {
            interiorTargets_.write(trialRows_[k], trialValues_.row(k).data(), dim, out);
        }
        made = true;
    }
    if (!returnReduce(made, andOp<bool>()))
    {
        return false;
    }
    prescribed_.insert(trialDisplacement_);

    // the correction and the constraints on the trial's field, in place of
    // the displacement's (exchanged, not copied)
    disp.swap(trialDisplacement_);
    error = correct(d);
    disp.swap(trialDisplacement_);

    // the points: 2D pairs over the whole field, else each point alone
    if (twoDPoints_.required())
    {
        twoDPoints_.move(points0_, trialDisplacement_, trialPoints_);
    }
    else
    {
        trialPoints_.setSize(disp.size());
        const pointField& p0 = points0_;
        for (const label pointi : points)
        {
            trialPoints_[pointi] = p0[pointi] + trialDisplacement_[pointi];
        }
    }
    return true;
}


// ************************************************************************* //
