// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: when the trial swaps of swapRule errorGuided are
// made, and how many. No mesh: a handful of numbers.
//
// A set that fits the motion gains nothing from trials: after a step whose
// trials were all undone (or abandoned) the next trials wait b steps
// (b = trialBackoff), and each further such step doubles the wait,
//
//     wait = b, 2b, 4b, ..., maxWait,
//
// a kept swap starting the back-off over at b. The wait ends early when the
// minimum cell quality (before the guard) has fallen by more than
// trialQualityDrop below that of the step that backed off: the set was found
// to fit a mesh that has since got worse.
//
// A rescue (the mesh without swaps has inverted cells) does not wait: up to
// rescueSwapFactor nSwap trials, and after an undone one up to rescueSkips
// further leaving points for the same joining point.
//
// Cost: O(1) everything.
//
// Contract, per step: endWaitIfWorse() (where the step's mesh was measured
// first), then the trials unless waiting(), backOff() if none was kept, or
// kept() once kept swaps are confirmed; endStep() at the end of every step,
// the step that backed off included (it counts as the first step waited).
// The restart state is wait(), backoff() and quality(); restart() puts it
// back.
#pragma once

namespace dcprbf
{

class TrialSchedule
{
public:
    //- A rescue makes at most this many times nSwap trials
    static const int rescueSwapFactor = 8;

    //- A rescue tries at most this many further leaving points for the
    //  same joining point after an undone trial
    static const int rescueSkips = 8;

    //- The wait and back-off before a step's trials (save(), restore())
    struct Saved
    {
        int wait;
        int backoff;
    };

    //- firstBackoff: trialBackoff; maxWait: the longest wait; qualityDrop:
    //  trialQualityDrop. No wait.
    TrialSchedule(int firstBackoff, int maxWait, double qualityDrop);

    //- Are the trials waiting (a rescue does not)?
    bool waiting() const { return wait_ > 0; }

    //- Steps left to wait
    int wait() const { return wait_; }

    //- The wait after the next undone trials
    int backoff() const { return backoff_; }

    //- The minimum quality (before the guard) of the step that backed off
    //  last (1 before any)
    double quality() const { return quality_; }

    //- trialBackoff, the first wait
    int firstBackoff() const { return firstBackoff_; }

    //- The trials of a step: nSwap, rescueSwapFactor nSwap in a rescue
    static int nTrials(bool rescue, int nSwap)
    {
        return (rescue ? rescueSwapFactor : 1)*nSwap;
    }

    //- After an undone trial: try the next leaving point (a rescue, up to
    //  rescueSkips times; counts skip)?
    static bool tryNextLeaving(bool rescue, int& skip)
    {
        return rescue && ++skip < rescueSkips;
    }

    //- End the wait if the minimum quality (without swaps, the same on every
    //  processor) has fallen by more than qualityDrop since the step that
    //  backed off; true if it has (a wait ended)
    bool endWaitIfWorse(double minQuality);

    //- The step's trials were all undone or abandoned: wait, and double the
    //  next wait (up to maxWait)
    void backOff();

    //- The step's swaps were kept: the back-off starts over
    void kept();

    //- End of step, given its minimum quality before the guard: the
    //  reference quality where the step backed off, a step less to wait
    void endStep(double minQuality);

    //- The wait and back-off, to put back with restore()
    Saved save() const { return Saved{wait_, backoff_}; }

    //- Put back a save() taken before this step's trials (a rescue after
    //  undone trials backs off as if they had not been made); the reference
    //  quality stays
    void restore(const Saved& s);

    //- From the restart state: wait(), backoff() and quality() as written
    void restart(int wait, int backoff, double quality);

private:
    int firstBackoff_;
    int maxWait_;
    double qualityDrop_;
    int wait_;
    int backoff_;
    double quality_;     // of the step that backed off last
    bool backedOff_;     // this step
};

} // namespace dcprbf
