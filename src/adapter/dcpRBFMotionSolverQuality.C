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

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFMotionSolver::measureQuality(dcpRBFStepLog::record& r)
{
    lastPoints_ = points0() + pointDisplacement_.primitiveField();
    twoDCorrectPoints(lastPoints_);
    lastQuality_ =
        region_.measure(lastPoints_, max(label(1), settings_.selection().nSwap));
    r.nCells = lastQuality_.nCells;
    r.minQuality = lastQuality_.minQuality;
    r.meanQuality = lastQuality_.meanQuality;
}


void Foam::dcpRBFMotionSolver::trySwaps
(
    const dcprbf::Values& d,
    dcpRBFStepLog::record& r
)
{
    if (!controlPoints_.canTrial())
    {
        return;
    }
    const dcpRBFQualityRegion::summary noSwap(lastQuality_);
    const vectorField noSwapField(pointDisplacement_.primitiveField());
    const pointField noSwapPoints(lastPoints_);
    const dcpRBFStepLog::record noSwapRecord(r);

    // up to nSwap trials, each kept only if the minimum quality improves
    for (label trial = 0; trial < settings_.selection().nSwap; ++trial)
    {
        const dcpRBFQualityRegion::summary q0(lastQuality_);
        if (q0.minQuality >= 1 - 1e-12 || !controlPoints_.proposeSwap(q0, d))
        {
            break;
        }
        const vectorField field0(pointDisplacement_.primitiveField());
        const pointField points0Copy(lastPoints_);
        const dcpRBFStepLog::record r0(r);
        r.boundaryError = interpolateDisplacement(d);
        measureQuality(r);
        if (lastQuality_.minQuality > q0.minQuality)
        {
            controlPoints_.keepSwap();
            continue;
        }
        controlPoints_.undoSwap(d);
        pointDisplacement_.primitiveFieldRef() = field0;
        lastPoints_ = points0Copy;
        lastQuality_ = q0;
        r = r0;
        ++r.nUndone;
        break;
    }
    const label kept = controlPoints_.endTrials(d);
    r.nAdded += kept;
    r.nRemoved += kept;
    if (kept && settings_.selection().swapBlendSteps > 1)
    {
        // the first blend step, not the whole swap: the mesh this step
        // writes must be better than without the swaps too
        r.boundaryError = interpolateDisplacement(d);
        measureQuality(r);
        if (!(lastQuality_.minQuality > noSwap.minQuality))
        {
            controlPoints_.abandonBlend(d);
            pointDisplacement_.primitiveFieldRef() = noSwapField;
            lastPoints_ = noSwapPoints;
            lastQuality_ = noSwap;
            r = noSwapRecord;
            r.nUndone += kept;
        }
    }
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
            if (settings_.onFloorFailure() == dcpRBFSettings::floorAction::stop)
            {
                FatalErrorInFunction
                    << "Time " << t << ": minimum cell quality " << q.minQuality
                    << " below qualityFloor " << floor << " after " << iter
                    << " guard additions (" << q.nInverted << " inverted"
                    << " cells). Stopping (qualityFloorAction stop)."
                    << exit(FatalError);
            }
            WarningInFunction
                << "Time " << t << ": minimum cell quality " << q.minQuality
                << " below qualityFloor " << floor << " after " << iter
                << " guard additions; continuing (qualityFloorAction warn)"
                << endl;
            break;
        }
        ++r.nGuard;
        controlPoints_.solve(d);
        r.boundaryError = interpolateDisplacement(d);
        measureQuality(r);
    }

    warnInverted(r);
}


void Foam::dcpRBFMotionSolver::warnInverted(const dcpRBFStepLog::record& r) const
{
    if (lastQuality_.nInverted)
    {
        WarningInFunction
            << "Time " << mesh().time().timeName() << ": "
            << lastQuality_.nInverted << " inverted or degenerate cells"
            << " (quality <= 0, minimum " << r.minQuality << "). The mesh is"
            << " invalid: "
            << (
                   rotation_.active()
                 ? "rotationInterpolation: the twist between the bodies and the"
                   " static patches is too large for the cells there (check"
                   " each body's centre is its pivot; refine the cells between"
                   " body and walls, or move the walls away)."
                 : "reduce the motion per step, enlarge supportRadius, use"
                   " selection dynamic with a qualityFloor, or, for large"
                   " rotations, rotationInterpolation true."
               )
            << endl;
    }
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
        lastQuality_ =
            region_.measure(p, max(label(1), settings_.selection().nSwap));
        lastPoints_ = p;
    }
    return lastQuality_;
}

// ************************************************************************* //
