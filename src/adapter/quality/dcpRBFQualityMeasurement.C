/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFQualityMeasurement.H"
#include "clockTime.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFQualityMeasurement::dcpRBFQualityMeasurement
(
    const dcpRBFContext& context,
    const bool rotation
)
:
    mesh_(context.mesh()),
    region_
    (
        mesh_, context.projection(), context.points0(),
        context.boundaryPoints().movingPoints(),
        dcpRBFQualityRegion::checkSources
        (
            mesh_, context.projection(), context.points0(),
            context.boundaryPoints()
        ),
        context.settings().kernel().radius(),
        context.settings().kernel().compact() && !rotation,
        context.settings().metric(),
        context.settings().movingReach(),
        &context.region()
    ),
    twoDPoints_(context.twoDPoints()),
    stepMesh_(context.stepMesh()),
    points0_(context.points0()),
    nRanked_(max(label(1), context.settings().selection().nSwap)),
    nLowest_(-1),
    rankBest_(true),
    measuredInStep_(false),
    checkTime_(0),
    nMeasurements_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFQualityMeasurement::measureRegion(const pointField& p)
{
    // the qualities into the last measurement's storage
    const label lowest = mesh_.time().writeTime() ? -1 : nLowest_;
    last_.summary = region_.measure
    (
        p, nRanked_, std::move(last_.summary.quality), lowest, rankBest_
    );
}


void Foam::dcpRBFQualityMeasurement::currentPoints(pointField& p) const
{
    // points0 + displacement (as Field's operator+), 2D corrected
    twoDPoints_.move(points0_, stepMesh_.displacement(), p);
}


void Foam::dcpRBFQualityMeasurement::measureLast()
{
    clockTime timer;
    last_.version = stepMesh_.version();
    measuredInStep_ = true;
    measureRegion(last_.points);
    ++nMeasurements_;
    checkTime_ += timer.elapsedTime();
}


void Foam::dcpRBFQualityMeasurement::startStep()
{
    measuredInStep_ = false;
}


void Foam::dcpRBFQualityMeasurement::measure()
{
    clockTime timer;
    currentPoints(last_.points);
    checkTime_ += timer.elapsedTime();
    measureLast();
}


void Foam::dcpRBFQualityMeasurement::measure(pointField& points)
{
    last_.points.transfer(points);
    measureLast();
}


const Foam::dcpRBFQualityRegion::summary&
Foam::dcpRBFQualityMeasurement::current()
{
    const pointField& p = mesh_.points();
    const pointField& last = last_.points;
    bool same = last.size() == p.size();
    for (label i = 0; same && i < p.size(); ++i)
    {
        same = (p[i] == last[i]);
    }
    if (!returnReduce(same, andOp<bool>()))
    {
        measureRegion(p);
        last_.points = p;
        last_.version = -1;     // the mesh's points: no version of ours
    }
    return last_.summary;
}


// ************************************************************************* //
