/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFSwapBlend.H"
#include "dcpRBFVersion.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFSwapBlend::dcpRBFSwapBlend(const label nSteps)
:
    nSteps_(nSteps),
    step_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dcpRBFSwapBlend::weight() const
{
    return scalar(step_)/nSteps_;
}


void Foam::dcpRBFSwapBlend::start(const dcprbf::DynamicControlSet::State& from)
{
    from_.reset(new dcprbf::DynamicControlSet::State(from));
    step_ = 1;
}


Foam::dcpRBFSwapBlend::held Foam::dcpRBFSwapBlend::take()
{
    held h;
    h.from = std::move(from_);
    h.step = step_;
    return h;
}


void Foam::dcpRBFSwapBlend::resume(held&& h)
{
    from_ = std::move(h.from);
    step_ = h.step;
}


void Foam::dcpRBFSwapBlend::advance()
{
    if (from_ && ++step_ >= nSteps_)
    {
        from_.reset();
    }
}


void Foam::dcpRBFSwapBlend::refresh(const dcprbf::DynamicControlSet& set)
{
    if (from_)
    {
        *from_ = set.freshState(from_->indices, from_->ages);
    }
}


void Foam::dcpRBFSwapBlend::write(dictionary& state) const
{
    if (from_)
    {
        state.set("blendStep", step_);
        state.set("blendFromIndices", dcpRBFCompat::makeList<label>(from_->indices));
        state.set("blendFromAges", dcpRBFCompat::makeList<label>(from_->ages));
    }
    else
    {
        state.remove("blendStep");
        state.remove("blendFromIndices");
        state.remove("blendFromAges");
    }
}


void Foam::dcpRBFSwapBlend::read
(
    const dictionary& state,
    const dcprbf::DynamicControlSet& set
)
{
    if (state.found("blendStep"))
    {
        step_ = state.get<label>("blendStep");
        const labelList from(state.get<labelList>("blendFromIndices"));
        const labelList fromAges(state.get<labelList>("blendFromAges"));
        from_.reset
        (
            new dcprbf::DynamicControlSet::State
            (
                set.freshState
                (
                    std::vector<Eigen::Index>(from.begin(), from.end()),
                    std::vector<int>(fromAges.begin(), fromAges.end())
                )
            )
        );
    }
}


// ************************************************************************* //
