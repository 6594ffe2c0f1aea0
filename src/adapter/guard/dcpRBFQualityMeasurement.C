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
    const polyMesh& mesh,
    const dcpRBFQualityRegion& region,
    const dcpRBFTwoDPoints& twoDPoints,
    const pointVectorField& pointDisplacement,
    const pointField& points0,
    const label nSwap
)
:
    mesh_(mesh),
    region_(region),
    twoDPoints_(twoDPoints),
    pointDisplacement_(pointDisplacement),
    points0_(points0),
    nRanked_(max(label(1), nSwap)),
    measured_(false),
    nMeasurements_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFQualityMeasurement::measureRegion(const pointField& p)
{
    // the qualities into the last measurement's storage
    last_ = region_.measure(p, nRanked_, std::move(last_.quality));
}


void Foam::dcpRBFQualityMeasurement::currentPoints(pointField& p) const
{
    // points0 + displacement (as Field's operator+), 2D corrected
    twoDPoints_.move(points0_, pointDisplacement_.primitiveField(), p);
}


void Foam::dcpRBFQualityMeasurement::measureLast(dcpRBFStepLog::record& r)
{
    measured_ = true;
    measureRegion(lastPoints_);
    ++nMeasurements_;
    r.nCells = last_.nChecked;
    r.nInverted = last_.checkedInverted;
    r.minQuality = last_.checkedMin;
    r.meanQuality = last_.checkedMean;
    r.regionMin = last_.minQuality;
}


void Foam::dcpRBFQualityMeasurement::measure(dcpRBFStepLog::record& r)
{
    currentPoints(lastPoints_);
    measureLast(r);
}


void Foam::dcpRBFQualityMeasurement::measure
(
    dcpRBFStepLog::record& r,
    pointField& points
)
{
    lastPoints_.transfer(points);
    measureLast(r);
}


void Foam::dcpRBFQualityMeasurement::measureTimed
(
    dcpRBFStepLog::record& r,
    pointField* points
)
{
    clockTime timer;
    if (points)
    {
        measure(r, *points);
    }
    else
    {
        measure(r);
    }
    r.guardTime += timer.elapsedTime();
}


const Foam::dcpRBFQualityRegion::summary&
Foam::dcpRBFQualityMeasurement::current()
{
    const pointField& p = mesh_.points();
    bool same = lastPoints_.size() == p.size();
    for (label i = 0; same && i < p.size(); ++i)
    {
        same = (p[i] == lastPoints_[i]);
    }
    if (!returnReduce(same, andOp<bool>()))
    {
        measureRegion(p);
        lastPoints_ = p;
        measured_ = false;     // the mesh's points: none of ours
    }
    return last_;
}


// ************************************************************************* //
