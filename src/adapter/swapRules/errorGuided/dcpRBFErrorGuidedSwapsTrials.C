/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFErrorGuidedSwaps, continued: the trial swaps, judged on the mesh
    of a window of cells (dcpRBFTrialMesh), and the mesh they give judged
    in full against the mesh without them (dcpRBFSavedStep).
\*---------------------------------------------------------------------------*/

#include "dcpRBFErrorGuidedSwaps.H"
#include "syncTools.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::dcpRBFErrorGuidedSwaps::canTrial(const bool rescue) const
{
    // the set ready, trials allowed, and a cell below the best quality in
    // the last measurement to pick the window from
    const dcpRBFQualityRegion::summary& last = quality_.last();
    return
        controlPoints_.ready()
     && (rescue || (!blend_.active() && !schedule_.waiting()))
     && context_.settings().selection().nSwap > 0
     && !last.worst.empty()
     && last.minQuality < 1 - 1e-12;
}


Foam::label Foam::dcpRBFErrorGuidedSwaps::trySwaps
(
    const dcprbf::Values& d,
    dcpRBFStepState& step,
    const bool measured
)
{
    // Rescue: without swaps the mesh has inverted cells; the trials do not
    // wait after fruitless ones, go on while they help (TrialSchedule)
    // and the swaps apply at once (no blend: an inverted mesh has no smooth
    // motion to keep)
    const trialStep ts{d, step, measured, measured && quality_.last().nInverted > 0};
    if (!canTrial(ts.rescue))
    {
        return 0;
    }
    step.rescue = ts.rescue;

    // Trials judged on the worst cells (of this step's mesh without swaps
    // if measured, else of the last step's mesh) and those around the
    // leaving points
    const bool atWindow =
        settings_.trialAt == dcpRBFErrorGuidedSettings::trialPoints::window;
    dcpRBFTrialMesh mesh
    (
        context_, quality_, interpolation_,
        atWindow ? &windowInterpolation_ : nullptr, d
    );
    // unmeasured: an inverted cell in the window without swaps: the mesh is
    // measured and rescued instead (afterInterpolate())
    if (!measured && mesh.startMin() <= 0)
    {
        quality_.measure(mesh.current());
        return 0;
    }
    dcpRBFSavedStep noSwaps(context_.stepMesh(), quality_, step.boundaryError);

    // Rescue during a blend: the blend ends at once, the trials start from
    // the new set's mesh (the blend is put back if nothing beats the mesh
    // without swaps)
    dcprbf::SwapBlend::Held blend;
    if (ts.rescue && blend_.active())
    {
        blend = finishBlend(d);
        step.boundaryError = mesh.remake();
    }

    runTrials(mesh, ts);
    const label kept = endTrials(d, !ts.rescue);
    if (mesh.windowed())
    {
        if (Pstream::parRun() && masterPoints_.empty())
        {
            masterPoints_ = syncTools::getMasterPoints(context_.mesh());
        }
        step.trialPoints = mesh.window().nGlobalPoints(masterPoints_);
    }
    if (kept || blend.from)
    {
        return keepIfBetter(ts, mesh, kept, std::move(blend), noSwaps);
    }
    // every trial undone: the mesh without swaps, measured (now if not yet:
    // no trial kept, the points without swaps)
    noSwaps.restore();
    if (!measured)
    {
        quality_.measure(mesh.current());
    }
    return 0;
}


void Foam::dcpRBFErrorGuidedSwaps::runTrials
(
    dcpRBFTrialMesh& mesh,
    const trialStep& ts
)
{
    // up to nSwap trials, each kept only if the window's minimum improves
    const label nTrials =
        dcprbf::TrialSchedule::nTrials
        (
            ts.rescue, context_.settings().selection().nSwap
        );
    int skip = 0;
    for (label i = 0; i < nTrials; ++i)
    {
        if
        (
            mesh.worst().quality() >= 1 - 1e-12
         || !trials_.propose(mesh.worst().centre(), ts.d, skip)
        )
        {
            break;
        }
        // the cells around the leaving point join the window, on the kept
        // set's mesh (not solved yet for the proposal)
        mesh.addAround
        (
            trials_.leaving(), leavingReachFraction*trials_.leavingReach()
        );
        if (trial(mesh, ts))
        {
            skip = 0;
            continue;
        }
        ++ts.state.nUndone;
        // rescue: the next leaving point instead, a few times
        if (!dcprbf::TrialSchedule::tryNextLeaving(ts.rescue, skip))
        {
            break;
        }
    }
}


bool Foam::dcpRBFErrorGuidedSwaps::trial
(
    dcpRBFTrialMesh& mesh,
    const trialStep& ts
)
{
    // the trial's mesh
    controlPoints_.solve(ts.d);
    const scalar error0 = ts.state.boundaryError;
    const dcpRBFTrialMesh::made m(mesh.ofSet(mesh.window().points()));
    const pointField& p = m.points;
    ts.state.boundaryError = mesh.error();
    const dcpRBFRankedCell w(mesh.window().worst(p));
    const bool improves = w.quality() > mesh.worst().quality();
    if (context_.debug())
    {
        // every digit: the trials of trialPoints window and all compare
        OStringStream msg;
        msg.precision(17);
        msg << "dcpRBF: trial swap on " << mesh.window().size()
            << " cells: minimum " << w.quality() << " against "
            << mesh.worst().quality() << ", sum " << mesh.window().sum(p)
            << (improves ? ", kept" : ", undone");
        Info<< msg.str().c_str() << endl;
    }
    if (improves)
    {
        trials_.keep();
        controlPoints_.setChanged();
        mesh.keep(m, w);
        return true;
    }
    // the set as before the trial (the displacement holds its mesh if the
    // trial did not change it: its version tells)
    trials_.undo();
    controlPoints_.solve(ts.d);
    ts.state.boundaryError = error0;
    return false;
}


Foam::label Foam::dcpRBFErrorGuidedSwaps::keepIfBetter
(
    const trialStep& ts,
    const dcpRBFTrialMesh& mesh,
    const label kept,
    dcprbf::SwapBlend::Held&& blend,
    dcpRBFSavedStep& noSwaps
)
{
    // The mesh this step writes (with swapBlendSteps > 1 the blend's first
    // step, not the whole swap; made anew unless the displacement is the
    // set's), measured in full: better than without the swaps, or they
    // are abandoned
    if (ts.measured)
    {
        noSwaps.setMeasurementAside();
    }
    const label blendSteps = settings_.swapBlendSteps;
    if ((kept && !ts.rescue && blendSteps > 1) || !mesh.fieldIsSet())
    {
        ts.state.boundaryError = interpolation_.interpolate(ts.d);
    }
    quality_.measure();
    // better than the window without swaps (and valid) is better than the
    // whole mesh without them; else that mesh is measured to compare
    const dcpRBFQualityRegion::summary& q = quality_.last();
    bool better = false;
    if (ts.measured)
    {
        better = q.minQuality > noSwaps.measurement().minQuality;
    }
    else if (q.nInverted == 0 && q.minQuality > mesh.startMin())
    {
        better = true;
    }
    else
    {
        // the mesh without swaps measured in its place to compare
        better = beatsUnswapped(noSwaps, ts.state);
    }
    if (better)
    {
        noSwaps.keep();
        ts.state.nAdded += kept;
        ts.state.nRemoved += kept;
        return kept;
    }
    abandonSwaps(ts.d);
    if (blend.from)
    {
        resumeBlend(std::move(blend), ts.d);
    }
    if (ts.measured)
    {
        noSwaps.restore();
    }
    else
    {
        // the mesh without swaps is in place, measured (beatsUnswapped())
        noSwaps.keep();
    }
    ts.state.nUndone += kept;
    return 0;
}


bool Foam::dcpRBFErrorGuidedSwaps::beatsUnswapped
(
    const dcpRBFSavedStep& noSwaps,
    dcpRBFStepState& step
)
{
    // the swapped mesh aside, the mesh without swaps measured in its place
    dcpRBFStepMesh& stepMesh = context_.stepMesh();
    dcpRBFSavedStep swapped(stepMesh, quality_, step.boundaryError);
    swapped.setMeasurementAside();
    stepMesh.change().primitiveFieldRef() = noSwaps.displacement();
    step.boundaryError = noSwaps.boundaryError();
    quality_.measure();
    // (without swaps inverted: abandoned, the rescue follows, as it would
    // have had that mesh been measured first)
    if
    (
        quality_.last().nInverted == 0
     && swapped.measurement().minQuality > quality_.last().minQuality
    )
    {
        swapped.restore();
        return true;
    }
    swapped.keep();
    return false;
}


// ************************************************************************* //
