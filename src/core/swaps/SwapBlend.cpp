// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "SwapBlend.hpp"

#include <utility>

namespace dcprbf
{

SwapBlend::SwapBlend(int nSteps)
:
    nSteps_(nSteps),
    step_(0)
{}


double SwapBlend::weight() const
{
    return double(step_)/nSteps_;
}


void SwapBlend::start(const DynamicControlSet::State& from)
{
    from_.reset(new DynamicControlSet::State(from));
    step_ = 1;
}


SwapBlend::Held SwapBlend::take()
{
    Held h;
    h.from = std::move(from_);
    h.step = step_;
    return h;
}


void SwapBlend::resume(Held&& held)
{
    from_ = std::move(held.from);
    step_ = held.step;
}


void SwapBlend::advance()
{
    if (from_ && ++step_ >= nSteps_)
    {
        from_.reset();
    }
}


void SwapBlend::refresh(const DynamicControlSet& set)
{
    if (from_)
    {
        *from_ = set.freshState(from_->indices, from_->ages);
    }
}


void SwapBlend::restart(int step, DynamicControlSet::State from)
{
    step_ = step;
    from_.reset(new DynamicControlSet::State(std::move(from)));
}

} // namespace dcprbf
