// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the phasing in of kept swaps (swapRule errorGuided,
// swapBlendSteps K): over K steps the interpolant goes from the set before
// the swaps to the set after them with weight
//
//     w = 1/K, 2/K, ..., 1      (start() gives 1/K, each advance() adds 1/K),
//
// the K-th step, of weight 1, the new set alone: active() for the first K - 1
// (a SetBlend), over once advance() reaches K. Holds the set being phased out
// (a DynamicControlSet::State) and the step.
//
// Cost: start() copies a state (O(N^2) numbers), refresh() factorizes the
// phased-out set afresh (O(N^3)); everything else is O(1).
//
// Contract:
//  - start() with the set before the swaps, for K >= 2 (K = 1: the swaps
//    at once, no blend started); advance() once at the end of every step;
//    stop() ends it at once.
//  - take() moves the blend out (it ends; a rescue makes the new set's mesh
//    alone) and resume() puts it back as it was.
//  - The restart state is step() and from()'s indices and ages (the adapter
//    writes them); restart() puts it back from a state factorized afresh, as
//    refresh() makes it at write times: a restart continues bit for bit.
#pragma once

#include "SetBlend.hpp"

#include <memory>

namespace dcprbf
{

class SwapBlend : public SetBlend
{
public:
    //- A blend taken out: the set it phases out (null: none) and its step
    struct Held
    {
        std::unique_ptr<DynamicControlSet::State> from;
        int step = 0;
    };

    //- nSteps: swapBlendSteps K; no blend
    explicit SwapBlend(int nSteps);

    bool active() const override { return bool(from_); }
    const DynamicControlSet::State& from() const override { return *from_; }
    //- step()/K
    double weight() const override;

    //- Steps into the blend (1 after start())
    int step() const { return step_; }

    //- Start phasing out the set from (weight 1/K)
    void start(const DynamicControlSet::State& from);

    //- End the blend (the new set alone)
    void stop() { from_.reset(); }

    //- Take the blend out (it ends), to put back with resume()
    Held take();

    //- Put a blend taken out back
    void resume(Held&& held);

    //- End of step: a step further, the blend over when it reaches K
    void advance();

    //- The phased-out set factorized afresh from its indices and ages (as
    //  a restart makes it); nothing without a blend. Throws Error if it
    //  cannot be factorized.
    void refresh(const DynamicControlSet& set);

    //- From the restart state: the blend at step, phasing out from
    void restart(int step, DynamicControlSet::State from);

private:
    int nSteps_;
    std::unique_ptr<DynamicControlSet::State> from_;   // null: no blend
    int step_;
};

} // namespace dcprbf
