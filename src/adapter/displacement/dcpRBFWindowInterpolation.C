/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFWindowInterpolation.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFWindowInterpolation::dcpRBFWindowInterpolation
(
    const dcpRBFContext& context,
    dcpRBFInterpolation& interpolation
)
:
    context_(context),
    interpolation_(interpolation)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFWindowInterpolation::setRows(const labelUList& points)
{
    // the distinct rows of the interior points among them and of the
    // finished points (those once, at the first use: marked 1 for good),
    // ascending
    const dcprbf::DistinctRows& distinct = context_.distinct();
    const dcpRBFBoundaryPoints& boundary = context_.boundaryPoints();
    const dcpRBFBoundaryPoints::pointKind* kind = boundary.kinds().cdata();
    const auto addRows = [&](const labelUList& pts, const char mark)
    {
        for (const label pointi : pts)
        {
            if (kind[pointi] == dcpRBFBoundaryPoints::interiorPoint)
            {
                const label row = distinct.of(pointi);
                if (!rowMarks_[row])
                {
                    rowMarks_[row] = mark;
                    rows_.push_back(int(row));
                }
            }
        }
        std::sort(rows_.begin(), rows_.end());
    };
    if (rowMarks_.empty())
    {
        rowMarks_.resize(distinct.points().rows(), 0);
        rows_.clear();
        addRows(interpolation_.prescribed().finishedPoints(), 1);
        finishedRows_ = rows_;
    }
    rows_.clear();
    addRows(points, 2);
    for (const int row : rows_)
    {
        rowMarks_[row] = 0;
    }
    const std::ptrdiff_t nWindow = rows_.size();
    rows_.insert(rows_.end(), finishedRows_.begin(), finishedRows_.end());
    std::inplace_merge(rows_.begin(), rows_.begin() + nWindow, rows_.end());
}


void Foam::dcpRBFWindowInterpolation::makePoints(const labelUList& points)
{
    const pointField& p0 = context_.points0();
    if (context_.twoDPoints().required())
    {
        context_.twoDPoints().move(p0, displacement_, points_);
    }
    else
    {
        points_.setSize(displacement_.size());
        for (const label pointi : points)
        {
            points_[pointi] = p0[pointi] + displacement_[pointi];
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dcpRBFWindowInterpolation::interpolate
(
    const dcprbf::Values& d,
    const labelUList& points,
    scalar& error
)
{
    const vectorField& disp = context_.pointDisplacement().primitiveField();
    if
    (
        !interpolation_.restrictable()
     || !returnReduce(disp.size() > 0, andOp<bool>())
    )
    {
        return false;
    }
    setRows(points);

    // (the field starts as the displacement of its first use: every value
    // finite where it is not made, never read there)
    if (displacement_.size() != disp.size())
    {
        displacement_ = disp;
    }
    const bool made = interpolation_.evaluateRows(rows_, displacement_, values_);
    if (!returnReduce(made, andOp<bool>()))
    {
        return false;
    }
    interpolation_.prescribed().insert(displacement_);

    // the correction and the constraints on this field, in place of the
    // displacement's
    error = interpolation_.correct(d, displacement_);
    makePoints(points);
    return true;
}


// ************************************************************************* //
