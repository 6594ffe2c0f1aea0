/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFTrialMesh.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFTrialMesh::dcpRBFTrialMesh
(
    const dcpRBFContext& context,
    dcpRBFQualityMeasurement& quality,
    dcpRBFInterpolation& interpolation,
    dcpRBFWindowInterpolation* windowInterpolation,
    const dcprbf::Values& d
)
:
    quality_(quality),
    interpolation_(interpolation),
    windowInterpolation_(windowInterpolation),
    stepMesh_(context.stepMesh()),
    d_(d),
    window_
    (
        context.mesh(), quality.region(), quality.last().quality,
        windowSize(quality.last().nCells), context.points0()
    ),
    complete_(true),
    startMin_(1),
    keptVersion_(stepMesh_.version()),
    windowed_(false),
    error_(0)
{
    // (assigned, not copy-constructed from a conditional: GCC 12 with
    // v2506's FixedList reports the copy's elements maybe-uninitialized)
    if (quality_.measured())
    {
        current_ = quality_.lastPoints();
        worst_ = quality_.last().worst[0];
    }
    else
    {
        quality_.currentPoints(current_);
        worst_ = window_.worst(current_);
    }
    startMin_ = worst_.quality();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::dcpRBFTrialMesh::made
Foam::dcpRBFTrialMesh::ofSet(const labelUList& points)
{
    if
    (
        windowInterpolation_
     && windowInterpolation_->interpolate(d_, points, error_)
    )
    {
        windowed_ = true;
        return made{windowInterpolation_->points(), false};
    }
    error_ = interpolation_.interpolate(d_);
    quality_.currentPoints(full_);
    return made{full_, true};
}


Foam::scalar Foam::dcpRBFTrialMesh::remake()
{
    const scalar error = interpolation_.interpolate(d_);
    keptVersion_ = stepMesh_.version();
    quality_.currentPoints(current_);
    worst_ = window_.worst(current_);
    return error;
}


void Foam::dcpRBFTrialMesh::addAround
(
    const Eigen::RowVector3d& x,
    const scalar radius
)
{
    // on the kept set's mesh (the proposal is not solved yet): made at the
    // new points first if that mesh is the window's alone
    window_.add(x, radius);
    if (!complete_ && returnReduce(window_.nAdded() > 0, orOp<bool>()))
    {
        const labelUList& all = window_.points();
        const SubList<label> added
        (
            all, window_.nAdded(), all.size() - window_.nAdded()
        );
        const made kept(ofSet(added));
        if (kept.complete)
        {
            keptVersion_ = stepMesh_.version();
            current_.transfer(full_);
            complete_ = true;
        }
        for (label i = 0; !complete_ && i < added.size(); ++i)
        {
            current_[added[i]] = kept.points[added[i]];
        }
    }
    worst_ = std::min(worst_, window_.worstAdded(current_));
}


void Foam::dcpRBFTrialMesh::keep
(
    const made& m,
    const dcpRBFRankedCell& w
)
{
    worst_ = w;
    if (m.complete)
    {
        keptVersion_ = stepMesh_.version();
        current_.transfer(full_);
        complete_ = true;
    }
    else
    {
        for (const label pointi : window_.points())
        {
            current_[pointi] = m.points[pointi];
        }
        keptVersion_ = -1;
        complete_ = false;
    }
}


// ************************************************************************* //
