// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the kernel of the incremental (updatable) solvers
//
//     K_c(x, y) = phi(|x - y|) + c q(x).q(y)
//
// with q the polynomial basis (LinearPolynomial) and c >= 0 a shift.
//
// Why: the saddle system  [Phi P; P^T 0] [alpha; beta] = [d; 0]  implies
// P^T alpha = 0, so replacing Phi by Phi_c = Phi + c P P^T changes neither
// alpha nor beta (Phi_c alpha = Phi alpha), and on the interpolant
// sum_j alpha_j K_c(x, c_j) = sum_j alpha_j phi(|x - c_j|) for every x.
//  - positive-definite kernels: c = 0, K_c = phi (plain Cholesky of Phi);
//  - the thin-plate spline is only conditionally positive definite (Phi is
//    positive definite on {alpha : P^T alpha = 0} only). Phi_c is positive
//    definite once c is large enough to lift the <= dim + 1 directions of
//    range(P); we start from c = 10 max|phi| over the polynomial frame's box
//    and the solvers multiply c by 10 (refactorizing) if a Cholesky pivot
//    still fails. With q in [-1, 1]^(dim+1) inside the box, this keeps Phi_c
//    within a factor ~10 of the scale of Phi.
// Cholesky then applies to every kernel, which is what makes appending and
// deleting control points an O(N^2) update for TPS too.
#pragma once

#include "LinearPolynomial.hpp"
#include "RadialKernel.hpp"

namespace dcprbf
{

class AugmentedKernel
{
public:
    //- The shift starts at initialShift(). Throws Error for TPS without
    //  the polynomial.
    AugmentedKernel(const RadialKernel& kernel, const LinearPolynomial& polynomial);

    const RadialKernel& kernel() const { return kernel_; }
    const LinearPolynomial& polynomial() const { return polynomial_; }

    //- c (0 for positive-definite kernels)
    double shift() const { return shift_; }

    //- Multiply c by 10 (TPS only; throws Error after 6 increases or for a
    //  positive-definite kernel, which never needs it)
    void increaseShift();

    //- 10 max_{0 <= r <= D} |phi(r)| for TPS (D: diagonal of the polynomial
    //  frame), 0 otherwise
    double initialShift() const;

    //- K_c(x, y) for one pair
    double operator()(const double* x, const double* y) const;

    //- K_c(x, x)
    double diagonal(const double* x) const;

    //- out[i] = K_c(x_i, y) for every row of x (threaded)
    void column(const Points& x, const double* y, double* out) const;

    //- K_c between the rows of a and b (threaded)
    Eigen::MatrixXd matrix(const Points& a, const Points& b) const;

    //- out[i] = phi(|x_i - y|), without the shift (threaded)
    void radialColumn(const Points& x, const double* y, double* out) const;

    //- phi(|a_i - b_j|), without the shift (threaded)
    Eigen::MatrixXd radialMatrix(const Points& a, const Points& b) const;

private:
    RadialKernel kernel_;
    LinearPolynomial polynomial_;
    double shift_;
    int increases_;
};

} // namespace dcprbf
