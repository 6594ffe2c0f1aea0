/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFBoundaryBlock.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFBoundaryBlock::dcpRBFBoundaryBlock
(
    const dcpRBFBoundaryPoints& boundary,
    const dcprbf::RadialKernel& kernel,
    const dcprbf::LinearPolynomial& polynomial
)
:
    begin_(begin(boundary.size(), Pstream::myProcNo())),
    points_
    (
        boundary.points().middleRows
        (
            begin_, begin(boundary.size(), Pstream::myProcNo() + 1) - begin_
        )
    ),
    blocks_(label(points_.rows())),
    stored_(kernel, polynomial, points_)
{
    for (Eigen::Index i = 0; i < points_.rows(); ++i)
    {
        if (boundary.moving()[begin_ + label(i)]) moving_.push_back(i);
    }
    movingPoints_.resize(Eigen::Index(moving_.size()), 3);
    for (std::size_t k = 0; k < moving_.size(); ++k)
    {
        movingPoints_.row(k) = points_.row(moving_[k]);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFBoundaryBlock::begin(const label n, const label proci)
{
    return label((int64_t(n)*proci)/Pstream::nProcs());
}


dcprbf::Values Foam::dcpRBFBoundaryBlock::values
(
    const dcprbf::RbfEvaluator& s,
    const std::size_t budget,
    const dcprbf::Points& otherwise,
    bool& stored
) const
{
    // the stored product of the same interpolant and budget kept (the
    // boundary error's check, then the correction, in one step)
    if (s.identity() == keptIdentity_ && budget == keptBudget_)
    {
        stored = true;
        return kept_;
    }
    dcprbf::Values v;
    stored = stored_.prepare(s.centres(), budget);
    if (stored)
    {
        stored_.evaluate(s.weights(), s.polynomialCoeffs(), v);
        kept_ = v;
        keptIdentity_ = s.identity();
        keptBudget_ = budget;
    }
    else
    {
        v = s.evaluate(otherwise);
    }
    return v;
}


dcprbf::Values Foam::dcpRBFBoundaryBlock::atBlock
(
    const dcprbf::RbfEvaluator& s,
    const std::size_t budget
) const
{
    bool stored;
    return values(s, budget, points_, stored);
}


Foam::scalar Foam::dcpRBFBoundaryBlock::largestMovingError
(
    const dcprbf::RbfEvaluator& s,
    const dcprbf::Values& d,
    const std::size_t budget,
    label& worst
) const
{
    // stored: at every candidate of the block, one product; else the
    // block's moving ones alone
    bool stored;
    const dcprbf::Values v(values(s, budget, movingPoints_, stored));
    scalar err = 0;
    label mine = -1;
    for (std::size_t k = 0; k < moving_.size(); ++k)
    {
        const Eigen::Index i = moving_[k];
        const scalar e =
            (v.row(stored ? i : Eigen::Index(k)) - d.row(begin_ + i)).norm();
        if (e > err)
        {
            err = e;
            mine = begin_ + label(i);
        }
    }
    // the largest over the blocks, ties to the lowest global index (none
    // where every error is zero)
    scalar largest = err;
    reduce(largest, maxOp<scalar>());
    worst = mine >= 0 && err == largest ? mine : labelMax;
    reduce(worst, minOp<label>());
    if (worst == labelMax)
    {
        worst = -1;
    }
    return largest;
}


// ************************************************************************* //
