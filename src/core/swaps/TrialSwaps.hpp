// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: one step's trial swaps on a control set (swapRule
// errorGuided). Each proposed swap changes the set and is then kept or
// undone; at the end of the trials the swaps kept are confirmed, or the set
// goes back to what it was before the step's first trial (abandon()). Two
// SetTransactions: the trial under way, and the step's trials. It changes
// the set and never solves it: the caller (the adapter's
// dcpRBFErrorGuidedSwaps) solves after each change, measures and decides.
//
// Proposal, for the values d at the candidates (the caller solved the set
// for them) and the centre x of the worst cell:
//  - joining: among the joinNeighbours non-member candidates nearest to x,
//    the one of largest |error| / distance whose |error| is above
//    1e-9 max|d| (DynamicControlSet::mostInaccurateNear);
//  - leaving: the removable, old-enough control points by ascending
//    leave-one-out error (DynamicControlSet::removalOrder), after the first
//    skip of them, the first the solver accepts in a swap with it;
//  - its reach: the distance from the leaving point to the nearest
//    remaining control point (the interpolant loses a centre there).
//
// Cost: propose() O(N^3/3) (the leave-one-out errors; kept in the state a
// trial undone returns to) plus O(N^2) per swap tried and a state copy;
// keep(), end(), confirm() O(1); undo(), abandon() O(N^2) copies.
//
// Contract:
//  - After propose() true, keep() or undo() before the next propose().
//  - undo() puts back the set as before the proposal, abandon() as before
//    the step's first proposal (indices, ages, factorization: bit for bit).
//  - end() at the end of the trials returns the number kept since the
//    step's first proposal; none kept ends the step's trials (started()
//    false), else they stay started until confirm() or abandon().
//  - propose() false: no swap made, the set unchanged.
#pragma once

#include "SetTransaction.hpp"

namespace dcprbf
{

class TrialSwaps
{
public:
    //- Candidates among which the joining point is chosen
    static const int joinNeighbours = 8;

    //- Trials on set (which outlives them)
    explicit TrialSwaps(DynamicControlSet& set);

    //- Propose one swap from the values d (solved) and the centre of the
    //  worst cell of the mesh they gave, skipping the first skip leaving
    //  points. False: none proposed, the set unchanged
    bool propose(const Eigen::RowVector3d& worstCentre, const Values& d, int skip);

    //- Keep the proposed swap
    void keep();

    //- Undo the proposed swap (the set as before it)
    void undo();

    //- Were trials proposed this step (and not yet confirmed or abandoned)?
    bool started() const { return step_.open(); }

    //- The set before the step's first trial (started() only)
    const DynamicControlSet::State& stepStart() const { return step_.before(); }

    //- End of the trials: the number kept (none: the step's trials are over,
    //  started() false)
    int end();

    //- The kept swaps stay (end of step)
    void confirm() { step_.commit(); }

    //- The kept swaps are given up: the set as before the step's first trial
    void abandon() { step_.rollBack(); }

    //- The last proposed swap's leaving point and its reach (distance to the
    //  nearest remaining control point)
    const Eigen::RowVector3d& leaving() const { return leaving_; }
    double leavingReach() const { return leavingReach_; }

private:
    DynamicControlSet& set_;
    SetTransaction trial_;    // the trial under way
    SetTransaction step_;     // the step's trials, until confirmed or abandoned
    int nKept_;
    Eigen::RowVector3d leaving_;
    double leavingReach_;
};

} // namespace dcprbf
