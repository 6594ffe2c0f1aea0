/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFTrialState.H"
#include "dcpRBFVersion.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFTrialState::write
(
    const dcprbf::TrialSchedule& schedule,
    dictionary& state
)
{
    state.set("trialWait", label(schedule.wait()));
    state.set("trialBackoff", label(schedule.backoff()));
    state.set("trialQuality", scalar(schedule.quality()));
}


void Foam::dcpRBFTrialState::read
(
    const dictionary& state,
    dcprbf::TrialSchedule& schedule
)
{
    const label wait = state.getOrDefault<label>("trialWait", 0);
    const label backoff =
        state.getOrDefault<label>("trialBackoff", schedule.firstBackoff());
    const scalar quality = state.getOrDefault<scalar>("trialQuality", 1);
    schedule.restart(wait, backoff, quality);
}


void Foam::dcpRBFTrialState::write
(
    const dcprbf::SwapBlend& blend,
    dictionary& state
)
{
    if (blend.active())
    {
        state.set("blendStep", label(blend.step()));
        state.set
        (
            "blendFromIndices",
            dcpRBFCompat::makeList<label>(blend.from().indices)
        );
        state.set
        (
            "blendFromAges",
            dcpRBFCompat::makeList<label>(blend.from().ages)
        );
    }
    else
    {
        state.remove("blendStep");
        state.remove("blendFromIndices");
        state.remove("blendFromAges");
    }
}


void Foam::dcpRBFTrialState::read
(
    const dictionary& state,
    const dcprbf::DynamicControlSet& set,
    dcprbf::SwapBlend& blend
)
{
    if (state.found("blendStep"))
    {
        const label step = state.get<label>("blendStep");
        const labelList from(state.get<labelList>("blendFromIndices"));
        const labelList fromAges(state.get<labelList>("blendFromAges"));
        blend.restart
        (
            step,
            set.freshState
            (
                std::vector<Eigen::Index>(from.begin(), from.end()),
                std::vector<int>(fromAges.begin(), fromAges.end())
            )
        );
    }
}


// ************************************************************************* //
