/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFMotionSolver, continued: the mesh quality after a step and the
    quality guard.
\*---------------------------------------------------------------------------*/

#include "dcpRBFMotionSolver.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFMotionSolver::measureRegion(const pointField& p)
{
    // the qualities into the last measurement's storage
    lastQuality_ = region_.measure
    (
        p, max(label(1), settings_.selection().nSwap),
        std::move(lastQuality_.quality)
    );
}


void Foam::dcpRBFMotionSolver::measureQuality(dcpRBFStepLog::record& r)
{
    currentPoints(lastPoints_);
    measureLastPoints(r);
}


void Foam::dcpRBFMotionSolver::measureLastPoints(dcpRBFStepLog::record& r)
{
    pointsMeasured_ = true;
    measureRegion(lastPoints_);
    ++nMeasurements_;
    r.nCells = lastQuality_.nChecked;
    r.nInverted = lastQuality_.checkedInverted;
    r.minQuality = lastQuality_.checkedMin;
    r.meanQuality = lastQuality_.checkedMean;
    r.regionMin = lastQuality_.minQuality;
}


void Foam::dcpRBFMotionSolver::guardQuality
(
    const dcprbf::Values& d,
    dcpRBFStepLog::record& r
)
{
    const scalar floor = settings_.qualityFloor();
    for (label iter = 0; ; ++iter)
    {
        const dcpRBFQualityRegion::summary& q = lastQuality_;

        if (q.checkedMin >= floor || !q.hasLowest)
        {
            shortfallSteps_ = 0;
            break;
        }
        if
        (
            iter >= settings_.guardIterations()
         || !controlPoints_.ready()
         || !controlPoints_.addNear(q.lowest)
        )
        {
            const word t(mesh().time().timeName());
            const string why(guardShortfall(iter));
            if (settings_.onFloorFailure() == dcpRBFSettings::floorAction::stop)
            {
                FatalErrorInFunction
                    << "Time " << t << ": minimum cell quality " << q.checkedMin
                    << " below qualityFloor " << floor << " after " << iter
                    << " guard additions" << why.c_str() << " (" << q.checkedInverted
                    << " inverted cells). Stopping (qualityFloorAction stop)."
                    << exit(FatalError);
            }
            if (inFull(shortfallSteps_))
            {
                WarningInFunction
                    << "Time " << t << ": minimum cell quality " << q.checkedMin
                    << " below qualityFloor " << floor << " after " << iter
                    << " guard additions" << why.c_str()
                    << "; continuing (qualityFloorAction warn; under a flow"
                       " solver, qualityFloorAction stop ends the run here)"
                    << (
                           shortfallSteps_ > 1
                         ? ". Short of the floor for "
                           + Foam::name(shortfallSteps_)
                           + " steps in a row: this warning in full every "
                           + Foam::name(warningRepeat) + " steps"
                         : string()
                       ).c_str()
                    << endl;
            }
            break;
        }
        ++r.nGuard;
        controlPoints_.solve(d);
        r.boundaryError = interpolateDisplacement(d);
        measureQuality(r);
    }

    warnInverted(r);
    warnLowQuality(r);
}


const Foam::dcpRBFQualityRegion::summary&
Foam::dcpRBFMotionSolver::currentQuality()
{
    const pointField& p = mesh().points();
    bool same = lastPoints_.size() == p.size();
    for (label i = 0; same && i < p.size(); ++i)
    {
        same = (p[i] == lastPoints_[i]);
    }
    if (!returnReduce(same, andOp<bool>()))
    {
        measureRegion(p);
        lastPoints_ = p;
        pointsMeasured_ = false;     // the mesh's points: none of ours
    }
    return lastQuality_;
}


// ************************************************************************* //
