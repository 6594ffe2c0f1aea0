/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFErrorGuidedSwaps, continued: the trial swaps, judged on the mesh
    of a window of cells (dcpRBFTrialWindow), made at the window's points
    alone where it can be (dcpRBFInterpolation::interpolateAt).
\*---------------------------------------------------------------------------*/

#include "dcpRBFErrorGuidedSwaps.H"
#include "dcpRBFMotionSolver.H"
#include "dcpRBFTrialWindow.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFErrorGuidedSwaps::trySwaps
(
    const dcprbf::Values& d,
    dcpRBFStepState& step,
    const bool measured
)
{
    // Rescue: without swaps the mesh has inverted cells; the trials do not
    // wait after fruitless ones, go on while they help (dcpRBFTrialSchedule)
    // and the swaps apply at once (no blend: an inverted mesh has no smooth
    // motion to keep)
    const bool rescue = measured && quality_.last().nInverted > 0;
    if
    (
        !controlPoints_.canTrial(rescue)
     || quality_.last().worst.empty()
     || quality_.last().minQuality >= 1 - 1e-12
    )
    {
        return 0;
    }
    const label nTrials =
        dcpRBFTrialSchedule::nTrials(rescue, settings_.selection().nSwap);
    const bool atWindow =
        settings_.selection().trialAt == dcpRBFSelectionSettings::trialPoints::window;
    step.rescue = rescue;

    // Trials judged on the worst cells (of this step's mesh without swaps
    // if measured, else of the last step's mesh) and those around the
    // leaving points
    const label nWindow =
        max(minTrialWindow, label(trialWindowFraction*quality_.last().nCells));
    dcpRBFTrialWindow window
    (
        mesh_, region_, quality_.last().quality, nWindow, points0_
    );
    // the mesh of the set kept so far: at every point (complete), or, once
    // a trial made at the window's points alone is kept, at those
    pointField current;
    if (measured)
    {
        current = quality_.lastPoints();
    }
    else
    {
        quality_.currentPoints(current);
    }
    // (assigned, not copy-constructed from a conditional: GCC 12 with
    // v2506's FixedList reports the copy's elements maybe-uninitialized)
    dcpRBFRankedCell worst;
    if (measured)
    {
        worst = quality_.last().worst[0];
    }
    else
    {
        worst = window.worst(current);
    }
    // unmeasured: the window's minimum without swaps, at least the mesh's;
    // an inverted cell there: the mesh is measured and rescued instead
    // (afterInterpolate())
    const scalar noSwapWindowMin = worst.quality();
    if (!measured && noSwapWindowMin <= 0)
    {
        quality_.measure(current);
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
    const bool noSwapMeasured = quality_.measured();
    const scalar noSwapError = step.boundaryError;

    // The mesh of the current evaluator at these of the window's points
    // (at every point if it cannot be restricted: in the displacement)
    scalar error = 0;
    pointField full;
    const auto meshOfSet = [&](const labelUList& pts) -> const pointField&
    {
        if (atWindow && interpolation_.interpolateAt(d, pts, error))
        {
            windowed = true;
            return interpolation_.trialPoints();
        }
        error = interpolate(d);
        fieldIsSet = fieldChanged = true;
        quality_.currentPoints(full);
        return full;
    };

    // Rescue during a blend: the blend ends at once, the trials start from
    // the new set's mesh (the blend is put back if nothing beats the mesh
    // without swaps)
    dcpRBFControlPoints::blendState blend;
    if (rescue && controlPoints_.blending())
    {
        blend = controlPoints_.finishBlend(d);
        step.boundaryError = interpolate(d);
        fieldChanged = true;
        quality_.currentPoints(current);
        worst = window.worst(current);
    }

    // up to nSwap trials, each kept only if the window's minimum improves
    label skip = 0;
    for (label trial = 0; trial < nTrials; ++trial)
    {
        if
        (
            worst.quality() >= 1 - 1e-12
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
        const scalar error0 = step.boundaryError;
        const pointField& p = meshOfSet(window.points());
        step.boundaryError = error;
        const dcpRBFRankedCell w(window.worst(p));
        if (dcpRBFMotionSolver::debug)
        {
            // every digit: the trials of trialPoints window and all compare
            OStringStream msg;
            msg.precision(17);
            msg << dcpRBFMotionSolver::typeName << ": trial swap on " << window.size()
                << " cells: minimum " << w.quality() << " against " << worst.quality()
                << ", sum " << window.sum(p)
                << (w.quality() > worst.quality() ? ", kept" : ", undone");
            Info<< msg.str().c_str() << endl;
        }
        if (w.quality() > worst.quality())
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
        step.boundaryError = error0;
        ++step.nUndone;
        // rescue: the next leaving point instead, a few times
        if (!dcpRBFTrialSchedule::tryNextLeaving(rescue, skip))
        {
            break;
        }
    }
    const label kept = controlPoints_.endTrials(d, !rescue);
    if (windowed)
    {
        step.trialPoints = pointCount_.count(window.points());
    }
    if (!kept && !blend.from)
    {
        // the mesh without swaps (every trial undone), measured in
        // quality_.last() and quality_.lastPoints() (now if not yet)
        if (fieldChanged)
        {
            pointDisplacement_.primitiveFieldRef() = noSwapField;
        }
        quality_.setMeasured(noSwapMeasured);
        if (!measured)
        {
            // (current: no trial kept, the points without swaps)
            quality_.measure(current);
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
        noSwap = std::move(quality_.last());
        noSwapPoints = std::move(quality_.lastPoints());
    }
    if ((kept && !rescue && settings_.selection().swapBlendSteps > 1) || !fieldIsSet)
    {
        step.boundaryError = interpolate(d);
    }
    quality_.measure();
    // better than the window without swaps (and valid) is better than the
    // whole mesh without them; else that mesh is measured to compare
    const bool better =
        measured
      ? quality_.last().minQuality > noSwap.minQuality
      : (quality_.last().nInverted == 0 && quality_.last().minQuality > noSwapWindowMin)
     || beatsUnswapped(noSwapField, noSwapError, step);
    if (better)
    {
        step.nAdded += kept;
        step.nRemoved += kept;
        return kept;
    }
    controlPoints_.abandonSwaps(d);
    if (blend.from)
    {
        controlPoints_.resumeBlend(std::move(blend), d);
    }
    if (measured)
    {
        pointDisplacement_.primitiveFieldRef() = noSwapField;
        quality_.last() = std::move(noSwap);
        quality_.lastPoints().transfer(noSwapPoints);
        quality_.setMeasured(noSwapMeasured);
        step.boundaryError = noSwapError;
    }
    // (else the mesh without swaps is in place, measured: see beatsUnswapped)
    step.nUndone += kept;
    return 0;
}


// ************************************************************************* //
