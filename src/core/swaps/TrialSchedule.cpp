// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "TrialSchedule.hpp"

#include <algorithm>

namespace dcprbf
{

TrialSchedule::TrialSchedule(int firstBackoff, int maxWait, double qualityDrop)
:
    firstBackoff_(firstBackoff),
    maxWait_(maxWait),
    qualityDrop_(qualityDrop),
    wait_(0),
    backoff_(firstBackoff),
    quality_(1),
    backedOff_(false)
{}


bool TrialSchedule::endWaitIfWorse(double minQuality)
{
    if (wait_ > 0 && quality_ - minQuality > qualityDrop_)
    {
        // the mesh has got worse since the set was found to fit it
        wait_ = 0;
        return true;
    }
    return false;
}


void TrialSchedule::backOff()
{
    wait_ = backoff_;
    backedOff_ = true;
    backoff_ = std::min(2*backoff_, maxWait_);
}


void TrialSchedule::kept()
{
    backoff_ = firstBackoff_;
}


void TrialSchedule::endStep(double minQuality)
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


void TrialSchedule::restore(const Saved& s)
{
    wait_ = s.wait;
    backoff_ = s.backoff;
    backedOff_ = false;
}


void TrialSchedule::restart(int wait, int backoff, double quality)
{
    wait_ = wait;
    backoff_ = backoff;
    quality_ = quality;
}

} // namespace dcprbf
