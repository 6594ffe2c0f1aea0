// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the factorized saddle system of an ordered set of
// centres, updated in O(N^2) when a centre is appended or deleted.
//
//     [ Phi_c  P ] [alpha]   [d]        Phi_c = Phi + c P P^T (AugmentedKernel,
//     [ P^T    0 ] [beta ] = [0]        c = 0 except for TPS)
//
// State:  Phi_c = L L^T (UpdatableCholesky),  W = L^{-1} P (N x m),
//         S = W^T W = P^T Phi_c^{-1} P (m x m, Cholesky; m = dim + 1 or 0).
// Solve:  y = L^{-1} d,  beta = S^{-1} W^T y,  alpha = L^{-T} (y - W beta).
// Append x:  l = L^{-1} k_c(C, x),  pivot = sqrt(K_c(x, x) - l.l),
//            w = (q(x) - W^T l)/pivot appended to W;            O(N^2)
// Delete i:  Givens downdate of L, the same rotations on W;     O(N^2)
// S is rebuilt from W after every change (O(N m^2)); while N < m (a set
// built point by point) it is not formed, and solve() needs N >= m.
//
// TPS (c > 0): the forward error of the shifted Cholesky grows like c, so
// solve() adds two steps of iterative refinement with the residual of the
// true saddle system, r = d - Phi alpha - P beta, s = -P^T alpha, from the
// stored plain kernel matrix Phi (O(N) per append, O(N^2) moves per delete).
// This brings alpha to the accuracy of an LU solve of the saddle matrix for
// two more O(N^2) solves.
//
// No input checks here (IncrementalSaddleSolver and GreedySelector do them).
#pragma once

#include "AugmentedKernel.hpp"
#include "UpdatableCholesky.hpp"

#include <Eigen/Cholesky>

namespace dcprbf
{

class SaddleFactorization
{
public:
    SaddleFactorization(const RadialKernel& kernel, const LinearPolynomial& polynomial);

    //- Factorize from scratch, O(N^3), starting from the initial shift and
    //  raising it (TPS) until Phi_c is positive definite. Throws Error (and
    //  leaves the factorization empty) when it cannot be.
    void factorize(const Points& centres);

    //- Empty set (keeps the shift and the storage)
    void clear() { n_ = 0; L_.clear(); inverseDiagonal_.resize(0); }

    //- Raise the shift tenfold, then factorize (TPS whose pivot failed)
    void raiseShiftAndFactorize(const Points& centres);

    //- For a new point x: l = L^{-1} k_c(C, x); returns pivot^2
    double newRow(const double* x, Eigen::VectorXd& l) const;

    //- pivot^2 above the round-off floor 1e-14 K_c(x, x)?
    bool acceptablePivot(const double* x, double pivotSq) const;

    //- Append x with its row l and pivot = sqrt(pivot^2) > 0
    void append(const double* x, const Eigen::VectorXd& l, double pivot);

    //- Delete centre i (later centres move down by one)
    void remove(Eigen::Index i);

    //- alpha (N x 3) and beta (m x 3) for values at the centres, O(N^2)
    void solve(const Values& values, Values& alpha, Eigen::MatrixX3d& beta) const;

    //- Diagonal of the kernel block of the saddle matrix's inverse,
    //  B = Phi_c^{-1} - Phi_c^{-1} P S^{-1} P^T Phi_c^{-1} (the same for
    //  every shift c), from Z = L^{-1}: B_jj = |Z e_j|^2 - |R^{-T} W^T Z e_j|^2
    //  with S = R^T R. Rippa's leave-one-out error at centre j is
    //  alpha_j / B_jj. O(N^3/3 + N^2 m), kept until the factorization
    //  changes (a trial swap undone returns to a state that has it): the
    //  reference is valid until then; not to be called on one object from
    //  two threads at once (it stores what it computed)
    const Eigen::VectorXd& inverseDiagonal() const;

    //- S^{-1} G for an m x 3 matrix G
    Eigen::MatrixX3d schurSolve(const Eigen::MatrixX3d& G) const
    {
        return schur_.solve(G);
    }

    Eigen::Index size() const { return n_; }
    Points centres() const { return centres_.topRows(n_); }
    const AugmentedKernel& kernel() const { return kernel_; }
    const LinearPolynomial& polynomial() const { return kernel_.polynomial(); }
    const UpdatableCholesky& factor() const { return L_; }
    Eigen::Block<const Eigen::MatrixXd> W() const { return W_.topRows(n_); }

    //- Number of O(N^3) factorizations so far
    int factorizations() const { return factorizations_; }

private:
    bool refines() const { return !kernel_.kernel().positiveDefinite(); }
    void reserve(Eigen::Index n);
    void factorizeWithCurrentShift(const Points& centres);
    void updateSchur();

    //- Solve [Phi_c P; P^T 0] [alpha; beta] = [r; s]
    void solveFactored
    (
        const Eigen::MatrixX3d& r,
        const Eigen::MatrixX3d& s,
        Eigen::MatrixX3d& alpha,
        Eigen::MatrixX3d& beta
    ) const;

    AugmentedKernel kernel_;
    Points centres_;        // capacity rows, first n_ used
    Eigen::Index n_;
    UpdatableCholesky L_;
    Eigen::MatrixXd W_;     // capacity x m
    Eigen::MatrixXd phi_;   // capacity x capacity, plain Phi (TPS only)
    Eigen::LLT<Eigen::MatrixXd> schur_;
    int factorizations_;
    mutable Eigen::VectorXd inverseDiagonal_;   // empty: not known
};

} // namespace dcprbf
