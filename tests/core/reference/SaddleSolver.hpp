// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF test reference (not in libdcpRBF): dense solver of the RBF
// saddle-point system (paper eq. 5)
//
//     [ Phi  P ] [alpha]   [d]
//     [ P^T  0 ] [beta ] = [0]
//
// Phi (N x N) is the kernel matrix, P (N x m) the polynomial basis at the
// centres (m = 0 without polynomial, m = dim + 1 with it).
//
// Positive-definite kernels: Phi = L L^T (Cholesky); the polynomial is handled
// through the Schur complement S = W^T W with W = L^{-1} P, itself factorized by
// Cholesky. Then  y = L^{-1} d,  beta = S^{-1} W^T y,  alpha = L^{-T}(y - W beta).
// Conditionally positive-definite kernels (TPS): LU with partial pivoting of the
// whole saddle matrix.
#pragma once

#include "Types.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace dcprbf
{

class SaddleSolver
{
public:
    //- Factorize. Throws Error when the system is singular.
    SaddleSolver
    (
        const Eigen::MatrixXd& phi,
        const Eigen::MatrixXd& poly,
        bool positiveDefinite
    );

    //- Solve for the kernel weights (N x 3) and polynomial coefficients (m x 3)
    void solve(const Values& rhs, Values& alpha, Eigen::MatrixX3d& beta) const;

    Eigen::Index size() const { return n_; }

private:
    Eigen::Index n_;
    Eigen::Index m_;
    bool cholesky_;

    // Cholesky path
    Eigen::LLT<Eigen::MatrixXd> phiLLT_;
    Eigen::MatrixXd W_;
    Eigen::LLT<Eigen::MatrixXd> schurLLT_;

    // LU path
    Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

} // namespace dcprbf
