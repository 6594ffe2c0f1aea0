/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFErrorGuidedSwaps, continued: the trials' changes of the control
    set at the end of the trials (kept, phased in, abandoned), the blend
    ended and put back by a rescue, and the rule's restart state.
\*---------------------------------------------------------------------------*/

#include "dcpRBFErrorGuidedSwaps.H"
#include "dcpRBFTrialState.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::dcpRBFErrorGuidedSwaps::endTrials
(
    const dcprbf::Values& d,
    const bool blend
)
{
    if (!trials_.started())
    {
        return 0;
    }
    const label kept = trials_.end();
    if (kept == 0)
    {
        // the set fits the motion: try again later, less often while it does
        schedule_.backOff();
        return 0;
    }
    // the trials stay started until endStep() (the swaps confirmed: the
    // back-off starts over) or abandonSwaps()
    if (blend && settings_.swapBlendSteps > 1)
    {
        blend_.start(trials_.stepStart());
        controlPoints_.solve(d);
    }
    return kept;
}


void Foam::dcpRBFErrorGuidedSwaps::abandonSwaps(const dcprbf::Values& d)
{
    if (!trials_.started())
    {
        return;
    }
    trials_.abandon();
    blend_.stop();
    controlPoints_.setChanged();
    schedule_.backOff();
    controlPoints_.solve(d);
}


dcprbf::SwapBlend::Held
Foam::dcpRBFErrorGuidedSwaps::finishBlend(const dcprbf::Values& d)
{
    dcprbf::SwapBlend::Held b(blend_.take());
    controlPoints_.setChanged();
    controlPoints_.solve(d);
    return b;
}


void Foam::dcpRBFErrorGuidedSwaps::resumeBlend
(
    dcprbf::SwapBlend::Held&& b,
    const dcprbf::Values& d
)
{
    blend_.resume(std::move(b));
    controlPoints_.setChanged();
    controlPoints_.solve(d);
}


void Foam::dcpRBFErrorGuidedSwaps::storeState(dictionary& state) const
{
    dcpRBFTrialState::write(schedule_, state);
    dcpRBFTrialState::write(blend_, state);
}


void Foam::dcpRBFErrorGuidedSwaps::readState()
{
    const dcpRBFStateDictionary& state = controlPoints_.state();
    dcpRBFTrialState::read(state, schedule_);
    try
    {
        dcpRBFTrialState::read(state, controlPoints_.set(), blend_);
    }
    catch (const dcprbf::Error& e)
    {
        FatalErrorInFunction
            << "Cannot rebuild the control set being phased out from "
            << state.objectPath() << ": " << e.what() << nl << "    "
            << controlPoints_.whatToDo(e).c_str() << exit(FatalError);
    }
}


// ************************************************************************* //
