/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFTrialSchedule.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFTrialSchedule::dcpRBFTrialSchedule
(
    const label firstBackoff,
    const label maxWait,
    const scalar qualityDrop
)
:
    firstBackoff_(firstBackoff),
    maxWait_(maxWait),
    qualityDrop_(qualityDrop),
    wait_(0),
    backoff_(firstBackoff),
    quality_(1),
    backedOff_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dcpRBFTrialSchedule::endWaitIfWorse(const scalar minQuality)
{
    if
    (
        wait_ > 0
     && quality_ - minQuality > qualityDrop_
    )
    {
        // the mesh has got worse since the set was found to fit it
        wait_ = 0;
        return true;
    }
    return false;
}


void Foam::dcpRBFTrialSchedule::backOff()
{
    wait_ = backoff_;
    backedOff_ = true;
    backoff_ = min(2*backoff_, maxWait_);
}


void Foam::dcpRBFTrialSchedule::kept()
{
    backoff_ = firstBackoff_;
}


void Foam::dcpRBFTrialSchedule::endStep(const scalar minQuality)
{
    if (backedOff_)
    {
        quality_ = minQuality;
        backedOff_ = false;
    }
    if (wait_ > 0)
    {
        --wait_;
    }
}


void Foam::dcpRBFTrialSchedule::restore(const FixedList<label, 2>& s)
{
    wait_ = s[0];
    backoff_ = s[1];
    backedOff_ = false;
}


void Foam::dcpRBFTrialSchedule::write(dictionary& state) const
{
    state.set("trialWait", wait_);
    state.set("trialBackoff", backoff_);
    state.set("trialQuality", quality_);
}


void Foam::dcpRBFTrialSchedule::read(const dictionary& state)
{
    wait_ = state.getOrDefault<label>("trialWait", 0);
    backoff_ = state.getOrDefault<label>("trialBackoff", firstBackoff_);
    quality_ = state.getOrDefault<scalar>("trialQuality", 1);
}


// ************************************************************************* //
