// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: a control set drawn from a fixed set of candidate
// points (the boundary points), changed one point at a time: the dynamic
// control points of Niu, Lei & He (2017).
//
// Rules ("neighbouring" made precise):
//  - addNearest(x):    the candidate nearest to x that is not a control
//                      point joins the set (O(Nb) search, O(N^2) update). If
//                      the solver refuses it (numerically dependent point),
//                      the next nearest is tried, up to maxTries.
//  - removeNearest(x): the removable control point nearest to x leaves the
//                      set, skipping points added less than protectSteps
//                      steps ago; never below minPoints; a removal the
//                      solver refuses (polynomial no longer solvable) is
//                      skipped for the next nearest.
//  - maxPoints caps additions; swap() exchanges two points at constant size
//    (also at maxPoints).
// Error-guided swaps (the adapter's swapRule errorGuided) use:
//  - mostInaccurateNear(x): among the k candidates nearest to x that are not
//    control points, the one of largest |error| / distance to x (an error
//    distorts the cells within reach of it: the nearer, the more);
//  - removalOrder(): removable, old-enough control points by ascending
//    leave-one-out error (Rippa 1999: alpha_j / B_jj, all at once from the
//    factorization), i.e. what their removal would cost at their own place;
//  - state()/restore() to undo a trial, and solveBlended() to phase a swap
//    in over several steps: (1 - w) s_from + w s_this, one interpolant on the
//    union of both sets' centres.
// The polynomial frame is the candidates' bounding box, fixed for the life
// of the set, so coefficients keep their meaning through the changes.
#pragma once

#include "IncrementalSaddleSolver.hpp"
#include "RbfEvaluator.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace dcprbf
{

class DynamicControlSet
{
public:
    struct Options
    {
        Eigen::Index minPoints = 0;
        Eigen::Index maxPoints = std::numeric_limits<Eigen::Index>::max();
        int protectSteps = 3;
        int maxTries = 8;
    };

    //- removable[i]: candidate i may leave the set (e.g. on a moving patch)
    DynamicControlSet
    (
        const Points& candidates,
        const std::vector<char>& removable,
        const RadialKernel& kernel,
        bool polynomial,
        int dim,
        const Options& options
    );

    //- Start from these candidates (indices), O(N^3). Throws Error.
    void reset(const std::vector<Eigen::Index>& indices);

    //- Start from these candidates with their factorization, built in the
    //  same frame (e.g. by the GreedySelector on the same candidates): no
    //  refactorization. Throws Error if the sizes do not match.
    void reset
    (
        const std::vector<Eigen::Index>& indices,
        SaddleFactorization factorization
    );

    //- Factorize the current set from scratch (same order, ages kept), as
    //  reset(indices()) would: after it the state depends only on indices()
    //  and not on the history of updates (exact restarts). O(N^3).
    void refactorize();

    //- Candidate index of each centre, in the solver's order
    const std::vector<Eigen::Index>& indices() const { return indices_; }

    Eigen::Index size() const { return Eigen::Index(indices_.size()); }

    bool contains(Eigen::Index candidate) const { return inSet_[candidate]; }

    //- Add candidate i (not yet in the set). Throws Error if the solver
    //  refuses it; false (nothing done) at maxPoints
    bool add(Eigen::Index i);

    //- Ages of the centres (steps since each joined), in the solver's order
    const std::vector<int>& ages() const { return age_; }

    //- Restore ages after reset() (e.g. on restart)
    void setAges(const std::vector<int>& ages);

    //- The set's state: its solver, indices and ages (copyable)
    struct State
    {
        IncrementalSaddleSolver solver;
        std::vector<Eigen::Index> indices;
        std::vector<int> ages;
    };
    State state() const { return State{solver_, indices_, age_}; }

    //- The state of the set with these indices and ages, factorized from
    //  scratch (O(N^3)); the set itself is unchanged
    State freshState
    (
        const std::vector<Eigen::Index>& indices,
        const std::vector<int>& ages
    ) const;
    void restore(const State& s);

    //- Leave-one-out errors at the centres (rows in the solver's order) of
    //  the interpolant of these candidate values. O(N^3/3). A centre the
    //  polynomial needs (B_jj = 0: without it the polynomial is no longer
    //  determined, e.g. one of dim+1 centres) has an infinite error: it
    //  cannot leave (no division by zero)
    Values leaveOneOutErrors(const Values& candidateValues) const;

    //- Among the k (at most maxTries) non-member candidates nearest to x,
    //  the one of largest |error| / |x_i - x| whose |error| is above floor;
    //  else -1. The error of the current interpolant against these
    //  candidate values, computed at those k alone (O(k N))
    Eigen::Index mostInaccurateNear
    (
        const Eigen::RowVector3d& x,
        const Values& candidateValues,
        int k,
        double floor
    ) const;

    //- Candidate indices of the removable, old-enough centres, ascending
    //  |leave-one-out error| (rows in the solver's order); those of an
    //  infinite error (the polynomial needs them) are not among them
    std::vector<Eigen::Index> removalOrder(const Values& looErrors) const;

    //- Candidate in joins and control point out (candidate index) leaves in
    //  one O(N^2) update, at constant size. False (nothing changed) if the
    //  solver refuses either.
    bool swap(Eigen::Index in, Eigen::Index out);

    //- Solve this set and from for the same values and set the evaluator
    //  to (1 - w) s_from + w s_this (same frame, centres merged)
    void solveBlended(const Values& candidateValues, const State& from, double w);

    //- See the rules above. Return the candidate index, or -1 if none
    Eigen::Index addNearest(const Eigen::RowVector3d& x);
    Eigen::Index removeNearest(const Eigen::RowVector3d& x);

    //- Both rules at once, at constant size (also at minPoints = maxPoints):
    //  the non-member nearest to join joins, the removable old-enough
    //  member nearest to leave leaves, in one update. Returns whether a
    //  swap was made.
    bool swapNearest(const Eigen::RowVector3d& join, const Eigen::RowVector3d& leave);

    //- One more step has passed (ages of the points grow)
    void nextStep();

    //- Solve for the values at every candidate (rows: candidates) and set
    //  the evaluator. O(N^2) plus the evaluator's assign.
    void solve(const Values& candidateValues);

    const RbfEvaluator& evaluator() const { return evaluator_; }
    const IncrementalSaddleSolver& solver() const { return solver_; }
    const Points& candidates() const { return candidates_; }

private:

    //- Set the indices, membership flags and fresh ages
    void setIndices(const std::vector<Eigen::Index>& indices);
    //- Candidates ordered by distance to x, keeping those pred accepts
    template<class Pred>
    std::vector<Eigen::Index> nearestFirst
    (
        const Eigen::RowVector3d& x,
        const std::vector<Eigen::Index>& pool,
        Pred accept
    ) const;

    Points candidates_;
    std::vector<char> removable_;
    Options options_;
    IncrementalSaddleSolver solver_;
    RbfEvaluator evaluator_;

    std::vector<Eigen::Index> indices_;
    std::vector<char> inSet_;
    std::vector<int> age_;   // per centre, steps since it joined
};


// * * * * * * * * * * * * * * * Template definitions * * * * * * * * * * * * //

template<class Pred>
inline std::vector<Eigen::Index> DynamicControlSet::nearestFirst
(
    const Eigen::RowVector3d& x,
    const std::vector<Eigen::Index>& pool,
    Pred accept
) const
{
    std::vector<std::pair<double, Eigen::Index>> d;
    for (const Eigen::Index i : pool)
    {
        if (accept(i)) d.emplace_back((candidates_.row(i) - x).squaredNorm(), i);
    }
    const std::size_t n = std::min<std::size_t>(d.size(), options_.maxTries);
    std::partial_sort(d.begin(), d.begin() + n, d.end());
    std::vector<Eigen::Index> out(n);
    for (std::size_t k = 0; k < n; ++k) out[k] = d[k].second;
    return out;
}


} // namespace dcprbf
