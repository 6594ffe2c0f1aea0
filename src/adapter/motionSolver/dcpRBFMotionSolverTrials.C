/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFMotionSolver, continued: the error-guided trial swaps, judged on
    the mesh of a window of cells (dcpRBFTrialWindow), made at the window's
    points alone (dcpRBFMotionSolverTrialMesh.C), before or after the
    step's full measurement (dcpRBFMotionSolverTrialChecks.C).
\*---------------------------------------------------------------------------*/

#include "dcpRBFMotionSolver.H"
#include "dcpRBFTrialWindow.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFMotionSolver::trySwaps
(
    const dcprbf::Values& d,
    dcpRBFStepLog::record& r,
    const bool measured
)
{
    // Rescue: without swaps the mesh has inverted cells; the trials do not
    // wait after fruitless ones, go on while they help (up to
    // rescueSwapFactor nSwap) and the swaps apply at once (no blend: an
    // inverted mesh has no smooth motion to keep)
    const bool rescue = measured && lastQuality_.nInverted > 0;
    if
    (
        !controlPoints_.canTrial(rescue)
     || lastQuality_.worst.empty()
     || lastQuality_.minQuality >= 1 - 1e-12
    )
    {
        return 0;
    }
    const label nTrials =
        (rescue ? rescueSwapFactor : 1)*settings_.selection().nSwap;
    const bool atWindow =
        settings_.selection().trialAt == dcpRBFSelectionSettings::trialPoints::window;
    r.rescue = rescue;

    // Trials judged on the worst cells (of this step's mesh without swaps
    // if measured, else of the last step's mesh) and those around the
    // leaving points
    const label nWindow =
        max(minTrialWindow, label(trialWindowFraction*lastQuality_.nCells));
    dcpRBFTrialWindow window
    (
        mesh(), region_, lastQuality_.quality, nWindow, points0()
    );
    // the mesh of the set kept so far: at every point (complete), or, once
    // a trial made at the window's points alone is kept, at those
    pointField current;
    if (measured)
    {
        current = lastPoints_;
    }
    else
    {
        currentPoints(current);
    }
    dcpRBFQualityRegion::rankedCell worst
    (
        measured ? lastQuality_.worst[0] : window.worst(current)
    );
    // unmeasured: the window's minimum without swaps, at least the mesh's;
    // an inverted cell there: the mesh is measured and rescued instead
    // (solve())
    const scalar noSwapWindowMin = worst[0];
    if (!measured && noSwapWindowMin <= 0)
    {
        measureWhole(r, &current);
        return 0;
    }
    bool complete = true;
    // the displacement is the current evaluator's (made at the window's
    // points, a trial leaves it as it was), or was changed at all
    bool fieldIsSet = true;
    bool fieldChanged = false;
    // some mesh was made at the window's points alone
    bool windowed = false;
    const vectorField noSwapField(pointDisplacement_.primitiveField());
    const bool noSwapMeasured = pointsMeasured_;
    const dcpRBFStepLog::record noSwapRecord(r);

    // The mesh of the current evaluator at these of the window's points
    // (at every point if it cannot be restricted: in the displacement)
    scalar error = 0;
    pointField full;
    const auto meshOfSet = [&](const labelUList& pts) -> const pointField&
    {
        if (atWindow && interpolateAt(d, pts, error))
        {
            windowed = true;
            return trialPoints_;
        }
        error = interpolateDisplacement(d);
        fieldIsSet = fieldChanged = true;
        currentPoints(full);
        return full;
    };

    // Rescue during a blend: the blend ends at once, the trials start from
    // the new set's mesh (the blend is put back if nothing beats the mesh
    // without swaps)
    dcpRBFControlPoints::blendState blend;
    if (rescue && controlPoints_.blending())
    {
        blend = controlPoints_.finishBlend(d);
        r.boundaryError = interpolateDisplacement(d);
        fieldChanged = true;
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
        // the cells around the leaving point join the window, on the kept
        // set's mesh (not solved yet for the proposal): made at their
        // points first if that mesh is the window's alone
        window.add
        (
            controlPoints_.leaving(),
            leavingReachFraction*controlPoints_.leavingReach()
        );
        if (!complete && returnReduce(window.nAdded() > 0, orOp<bool>()))
        {
            const labelUList& all = window.points();
            const SubList<label> added
            (
                all, window.nAdded(), all.size() - window.nAdded()
            );
            const pointField& kept = meshOfSet(added);
            if (&kept == &full)
            {
                current.transfer(full);
                complete = true;
            }
            for (label i = 0; !complete && i < added.size(); ++i)
            {
                current[added[i]] = kept[added[i]];
            }
        }
        worst = std::min(worst, window.worstAdded(current));

        // the trial's mesh
        const bool setBefore = fieldIsSet;
        controlPoints_.solve(d);
        fieldIsSet = false;
        const scalar error0 = r.boundaryError;
        const pointField& p = meshOfSet(window.points());
        r.boundaryError = error;
        const dcpRBFQualityRegion::rankedCell w(window.worst(p));
        if (debug)
        {
            // every digit: the trials of trialPoints window and all compare
            OStringStream msg;
            msg.precision(17);
            msg << typeName << ": trial swap on " << window.size()
                << " cells: minimum " << w[0] << " against " << worst[0]
                << ", sum " << window.sum(p)
                << (w[0] > worst[0] ? ", kept" : ", undone");
            Info<< msg.str().c_str() << endl;
        }
        if (w[0] > worst[0])
        {
            controlPoints_.keepSwap();
            worst = w;
            if (&p == &full)
            {
                current.transfer(full);
                complete = true;
            }
            else
            {
                for (const label pointi : window.points())
                {
                    current[pointi] = p[pointi];
                }
                complete = false;
            }
            skip = 0;
            continue;
        }
        // the set as before the trial: so is the displacement if the trial
        // did not change it
        controlPoints_.undoSwap(d);
        fieldIsSet = !fieldIsSet && setBefore;
        r.boundaryError = error0;
        ++r.nUndone;
        // rescue: the next leaving point instead, a few times
        if (!rescue || ++skip >= rescueSkips)
        {
            break;
        }
    }
    const label kept = controlPoints_.endTrials(d, !rescue);
    if (windowed)
    {
        r.trialPoints = nGlobalPoints(window.points());
    }
    if (!kept && !blend.from)
    {
        // the mesh without swaps (every trial undone), measured in
        // lastQuality_ and lastPoints_ (now if not yet)
        if (fieldChanged)
        {
            pointDisplacement_.primitiveFieldRef() = noSwapField;
        }
        pointsMeasured_ = noSwapMeasured;
        if (!measured)
        {
            // (current: no trial kept, the points without swaps)
            measureWhole(r, &current);
        }
        return 0;
    }

    // The mesh this step writes (with swapBlendSteps > 1 the blend's first
    // step, not the whole swap; made anew unless the displacement is the
    // set's), measured in full: better than without the swaps, or they
    // are abandoned
    dcpRBFQualityRegion::summary noSwap;
    pointField noSwapPoints;
    if (measured)
    {
        noSwap = std::move(lastQuality_);
        noSwapPoints = std::move(lastPoints_);
    }
    if ((kept && !rescue && settings_.selection().swapBlendSteps > 1) || !fieldIsSet)
    {
        r.boundaryError = interpolateDisplacement(d);
    }
    measureWhole(r);
    // better than the window without swaps (and valid) is better than the
    // whole mesh without them; else that mesh is measured to compare
    const bool better =
        measured
      ? lastQuality_.minQuality > noSwap.minQuality
      : (lastQuality_.nInverted == 0 && lastQuality_.minQuality > noSwapWindowMin)
     || beatsUnswapped(noSwapField, noSwapRecord, r);
    if (better)
    {
        r.nAdded += kept;
        r.nRemoved += kept;
        return kept;
    }
    controlPoints_.abandonSwaps(d);
    if (blend.from)
    {
        controlPoints_.resumeBlend(std::move(blend), d);
    }
    const label nUndone = r.nUndone, trialPoints = r.trialPoints;
    if (measured)
    {
        pointDisplacement_.primitiveFieldRef() = noSwapField;
        lastQuality_ = std::move(noSwap);
        lastPoints_.transfer(noSwapPoints);
        pointsMeasured_ = noSwapMeasured;
        const scalar guardTime = r.guardTime;
        r = noSwapRecord;
        r.guardTime = guardTime;
    }
    // (else the mesh without swaps is in place, measured: see beatsUnswapped)
    r.nUndone = nUndone + kept;
    r.trialPoints = trialPoints;
    r.rescue = rescue;
    return 0;
}


// ************************************************************************* //
