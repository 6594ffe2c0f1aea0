/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFMotionSolver, continued: the mesh quality after a step, the
    error-guided trial swaps judged by it, and the quality guard.
\*---------------------------------------------------------------------------*/

#include "dcpRBFMotionSolver.H"
#include "dcpRBFTrialWindow.H"

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
    pointsMeasured_ = true;
    measureRegion(lastPoints_);
    r.nCells = lastQuality_.nCells;
    r.nInverted = lastQuality_.nInverted;
    r.minQuality = lastQuality_.minQuality;
    r.meanQuality = lastQuality_.meanQuality;
}


void Foam::dcpRBFMotionSolver::trySwaps
(
    const dcprbf::Values& d,
    dcpRBFStepLog::record& r
)
{
    // Rescue: without swaps the mesh has inverted cells; the trials do not
    // wait after fruitless ones, go on while they help (up to
    // rescueSwapFactor nSwap) and the swaps apply at once (no blend: an
    // inverted mesh has no smooth motion to keep)
    const bool rescue = lastQuality_.nInverted > 0;
    if
    (
        !controlPoints_.canTrial(rescue)
     || lastQuality_.worst.empty()
     || lastQuality_.minQuality >= 1 - 1e-12
    )
    {
        return;
    }
    const label nTrials =
        (rescue ? rescueSwapFactor : 1)*settings_.selection().nSwap;
    r.rescue = rescue;

    // Trials judged on the worst cells and those around the leaving points
    const label nWindow =
        max(minTrialWindow, label(trialWindowFraction*lastQuality_.nCells));
    dcpRBFTrialWindow window
    (
        mesh(), region_, lastQuality_.quality, nWindow, points0(),
        settings_.metric()
    );
    dcpRBFQualityRegion::rankedCell worst(lastQuality_.worst[0]);
    pointField current(lastPoints_);
    const vectorField noSwapField(pointDisplacement_.primitiveField());
    const bool noSwapMeasured = pointsMeasured_;
    const dcpRBFStepLog::record noSwapRecord(r);

    // Rescue during a blend: the blend ends at once, the trials start from
    // the new set's mesh (the blend is put back if nothing beats the mesh
    // without swaps)
    dcpRBFControlPoints::blendState blend;
    if (rescue && controlPoints_.blending())
    {
        blend = controlPoints_.finishBlend(d);
        r.boundaryError = interpolateDisplacement(d);
        current = curPoints();
        worst = window.worst(current);
    }

    // up to nSwap trials, each kept only if the window's minimum improves
    label skip = 0;
    for (label trial = 0; trial < nTrials; ++trial)
    {
        if
        (
            worst[0] >= 1 - 1e-12
         || !controlPoints_.proposeSwap(worst, d, skip)
        )
        {
            break;
        }
        // the cells around the leaving point join the window, as they are
        worst = std::min
        (
            worst,
            window.add
            (
                controlPoints_.leaving(),
                leavingReachFraction*controlPoints_.leavingReach(),
                current
            )
        );
        const vectorField field0(pointDisplacement_.primitiveField());
        const scalar error0 = r.boundaryError;
        r.boundaryError = interpolateDisplacement(d);
        pointField p(curPoints());
        const dcpRBFQualityRegion::rankedCell w(window.worst(p));
        if (w[0] > worst[0])
        {
            controlPoints_.keepSwap();
            worst = w;
            current.transfer(p);
            skip = 0;
            continue;
        }
        controlPoints_.undoSwap(d);
        pointDisplacement_.primitiveFieldRef() = field0;
        r.boundaryError = error0;
        ++r.nUndone;
        // rescue: the next leaving point instead, a few times
        if (!rescue || ++skip >= rescueSkips)
        {
            break;
        }
    }
    const label kept = controlPoints_.endTrials(d, !rescue);
    if (!kept && !blend.from)
    {
        // the mesh without swaps (every trial undone: the displacement
        // as before them), measured in lastQuality_ and lastPoints_
        pointsMeasured_ = noSwapMeasured;
        return;
    }

    // The mesh this step writes (with swapBlendSteps > 1 the blend's first
    // step, not the whole swap), measured in full: better than without the
    // swaps, or they are abandoned
    dcpRBFQualityRegion::summary noSwap(std::move(lastQuality_));
    pointField noSwapPoints(std::move(lastPoints_));
    if (!rescue && settings_.selection().swapBlendSteps > 1)
    {
        r.boundaryError = interpolateDisplacement(d);
    }
    measureQuality(r);
    if (lastQuality_.minQuality > noSwap.minQuality)
    {
        r.nAdded += kept;
        r.nRemoved += kept;
        return;
    }
    controlPoints_.abandonSwaps(d);
    if (blend.from)
    {
        controlPoints_.resumeBlend(std::move(blend), d);
    }
    pointDisplacement_.primitiveFieldRef() = noSwapField;
    lastQuality_ = std::move(noSwap);
    lastPoints_.transfer(noSwapPoints);
    pointsMeasured_ = noSwapMeasured;
    const label nUndone = r.nUndone;
    r = noSwapRecord;
    r.nUndone = nUndone + kept;
    r.rescue = rescue;
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

        if (q.minQuality >= floor || q.worst.empty())
        {
            shortfallSteps_ = 0;
            break;
        }
        if
        (
            iter >= settings_.guardIterations()
         || !controlPoints_.ready()
         || !controlPoints_.addNear(q.worst[0])
        )
        {
            const word t(mesh().time().timeName());
            const string why(guardShortfall(iter));
            if (settings_.onFloorFailure() == dcpRBFSettings::floorAction::stop)
            {
                FatalErrorInFunction
                    << "Time " << t << ": minimum cell quality " << q.minQuality
                    << " below qualityFloor " << floor << " after " << iter
                    << " guard additions" << why.c_str() << " (" << q.nInverted
                    << " inverted cells). Stopping (qualityFloorAction stop)."
                    << exit(FatalError);
            }
            if (inFull(shortfallSteps_))
            {
                WarningInFunction
                    << "Time " << t << ": minimum cell quality " << q.minQuality
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
