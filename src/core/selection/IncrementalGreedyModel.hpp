// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: residual of the greedy selection at every candidate,
// updated in O(N Nb) per added control point (Newton basis).
//
// With Phi_c = L L^T the Cholesky factor of the selected set C (kernel K_c,
// see AugmentedKernel) the Newton basis at a candidate x is
//     v(x) = L^{-1} k_c(C, x)                       (N values)
// and, with W = L^{-1} P, y = L^{-1} d_C, beta = S^{-1} W^T y, S = W^T W,
//     s(x) = k_c(C, x)^T alpha + q(x)^T beta
//          = v(x)^T y + (q(x) - W^T v(x))^T beta = a(x) + Q(x)^T beta.
// Appending the candidate c with l = v(c) (its current row) and
// pivot = sqrt(K_c(c, c) - l.l) (one more row of L):
//     v_new(x) = (K_c(x, c) - v(x).l)/pivot          for all x: O(N Nb)
//     y_new    = (d(c) - l.y)/pivot,   w_new = (q(c) - W^T l)/pivot
//     a(x) += v_new(x) y_new,   Q(x) -= v_new(x) w_new,   W^T y += w_new y_new
// and beta = S^{-1} W^T y (m x m). Nothing is re-solved; memory: the Nb x N
// Newton basis V (160 MB for Nb = 20000, N = 1000).
//
// A pivot below round-off (1e-14 K_c(c, c)) throws Error for positive-definite
// kernels (the candidate is numerically dependent on the selected ones); for
// TPS it raises the shift c tenfold and rebuilds V, y, a, Q from the
// refactorized set (O(N^2 Nb), rare), since s(x) does not depend on c.
//
// Divided over ranks (CandidateRows): each rank holds the rows of V, a, Q
// and the residual of its own candidates only (Nb/P x N); the appended
// candidate's coordinates, displacement and row l come from the rank that
// holds it (one broadcast of N + 6 values), after which every rank updates
// the replicated O(N^2) part (L, W, y) with the same values in the same
// order: the same factorization everywhere, bit for bit.
#pragma once

#include "CandidateRows.hpp"
#include "GreedyModel.hpp"
#include "SaddleFactorization.hpp"

#include <memory>

namespace dcprbf
{

class IncrementalGreedyModel : public GreedyModel
{
public:
    //- The model keeps references to candidates and displacements
    IncrementalGreedyModel
    (
        const RadialKernel& kernel,
        const LinearPolynomial& polynomial,
        const Points& candidates,
        const Values& displacements
    );

    //- This rank's block of the candidates (and the references it keeps);
    //  add() takes global indices, residual() is this rank's rows
    IncrementalGreedyModel
    (
        const RadialKernel& kernel,
        const LinearPolynomial& polynomial,
        const CandidateRows& rows
    );

    void add(const std::vector<Eigen::Index>& indices) override;
    const Values& residual() const override { return residual_; }
    void coefficients(Values& alpha, Eigen::MatrixX3d& beta) const override;

    //- Recompute V, y, a, Q from the current factorization (O(N^2 Nb)); the
    //  residual must not change (tests)
    void rebuild();

    //- Raise the TPS shift tenfold, refactorize, rebuild
    void raiseShiftAndRebuild();

    const SaddleFactorization& factorization() const { return *f_; }

    //- Hand the factorization over (the model is unusable afterwards)
    std::unique_ptr<SaddleFactorization> releaseFactorization() override
    {
        return std::move(f_);
    }

private:
    void append(Eigen::Index c);
    void raiseShiftAndRebuild(const Points& centres);
    void updateResidual();
    void reserve(Eigen::Index n);

    CandidateRows rows_;
    std::unique_ptr<SaddleFactorization> f_;
    std::vector<Eigen::Index> selected_;

    Eigen::MatrixXd V_;         // Nb x capacity, Newton basis at candidates
    Eigen::MatrixX3d y_;        // capacity x 3, Newton coefficients of d
    Eigen::MatrixX3d dSelected_; // capacity x 3, d at the selected points
    Eigen::MatrixX3d a_;        // Nb x 3,  V y
    Eigen::MatrixXd Q_;         // Nb x m,  q(x)^T - V W
    Eigen::MatrixX3d WTy_;      // m x 3
    Values residual_;           // Nb x 3
};

} // namespace dcprbf
