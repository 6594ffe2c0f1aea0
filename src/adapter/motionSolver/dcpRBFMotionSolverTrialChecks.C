/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFMotionSolver, continued: what the error-guided trials are checked
    with: whether they come before the step's full measurement, that
    measurement, the mesh without swaps measured to compare, and the log's
    count of the points their meshes were made at.
\*---------------------------------------------------------------------------*/

#include "dcpRBFMotionSolver.H"
#include "syncTools.H"
#include "clockTime.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFMotionSolver::nGlobalPoints(const labelUList& points)
{
    if (!Pstream::parRun())
    {
        return points.size();
    }
    if (!masterPointsMade_)
    {
        masterPoints_ = syncTools::getMasterPoints(mesh());
        masterPointsMade_ = true;
    }
    // a point in any processor's list, counted by its master
    // (labels: OpenFOAM's exchange of bools trips GCC's allocation-size
    // warning, an error in CI)
    labelList in(mesh().nPoints(), 0);
    for (const label pointi : points)
    {
        in[pointi] = 1;
    }
    syncTools::syncPointList(mesh(), in, maxEqOp<label>(), label(0));
    label n = 0;
    forAll(in, pointi)
    {
        if (in[pointi] && masterPoints_.test(pointi))
        {
            ++n;
        }
    }
    return returnReduce(n, sumOp<label>());
}


bool Foam::dcpRBFMotionSolver::trialsBeforeMeasure() const
{
    // trials due, not a rescue (the last step's mesh had no inverted cell),
    // and the last step's measurement to pick the window from
    return
        controlPoints_.canTrial(false)
     && lastQuality_.nCells > 0
     && lastQuality_.nInverted == 0
     && !lastQuality_.worst.empty()
     && lastQuality_.minQuality < 1 - 1e-12;
}


void Foam::dcpRBFMotionSolver::measureWhole
(
    dcpRBFStepLog::record& r,
    pointField* points
)
{
    clockTime timer;
    if (points)
    {
        lastPoints_.transfer(*points);
        measureLastPoints(r);
    }
    else
    {
        measureQuality(r);
    }
    r.guardTime += timer.elapsedTime();
}


bool Foam::dcpRBFMotionSolver::beatsUnswapped
(
    const vectorField& noSwapField,
    const dcpRBFStepLog::record& noSwapRecord,
    dcpRBFStepLog::record& r
)
{
    // the swapped mesh aside, the mesh without swaps measured in its place
    vectorField& disp = pointDisplacement_.primitiveFieldRef();
    vectorField swappedField(disp);
    dcpRBFQualityRegion::summary swapped(std::move(lastQuality_));
    pointField swappedPoints(std::move(lastPoints_));
    const dcpRBFStepLog::record swappedRecord(r);
    disp = noSwapField;
    r = noSwapRecord;
    r.nUndone = swappedRecord.nUndone;
    r.trialPoints = swappedRecord.trialPoints;
    r.guardTime = swappedRecord.guardTime;
    measureWhole(r);
    // (without swaps inverted: abandoned, the rescue follows, as it would
    // have had that mesh been measured first)
    if (lastQuality_.nInverted == 0 && swapped.minQuality > lastQuality_.minQuality)
    {
        const scalar guardTime = r.guardTime;
        disp.transfer(swappedField);
        lastQuality_ = std::move(swapped);
        lastPoints_.transfer(swappedPoints);
        pointsMeasured_ = true;
        r = swappedRecord;
        r.guardTime = guardTime;
        return true;
    }
    return false;
}


// ************************************************************************* //
