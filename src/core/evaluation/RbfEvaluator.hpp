// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: fast evaluation of a solved RBF interpolant
//
//     s(x) = sum_j alpha_j phi(|x - c_j|) + sum_i beta_i q_i(x)
//
// at many points (the mesh points), threaded with OpenMP over points.
//  - Tree: compact kernels, nanoflann radius search around x; cost per point
//    ~ (centres within R) + a tree descent.
//  - Dense: every centre, in blocks (64 points x 1024 centres, the centres and
//    weights copied into separate x/y/z arrays) so that a block of centres
//    stays in L1/L2 while 64 points use it; per point and block the kernel
//    values are one Eigen array expression (vectorized sqrt/log/exp, see
//    RadialKernel.hpp). Global kernels always use it.
//  - Auto (default): Tree for compact kernels unless a sample of 64 of the
//    query points sees more than 30 % of the centres on average, where the
//    tree costs more than it saves (large support radius).
//
// Reuse between steps: when the control set changes by a few points, every
// weight alpha_j changes (the saddle system couples them), so s(x) has to be
// summed over all centres again. The exact shortcut while the centres stay
// the same keeps the matrix phi(|x - c_j|) (StoredEvaluation: sparse for
// compact kernels, within a memory budget). assign() is O(N log N).
// identity() names the interpolant assigned: equal identities, the same
// centres, weights and polynomial coefficients, so that a caller may keep
// values it computed from them (dcpRBFBoundaryBlock).
#pragma once

#include "LinearPolynomial.hpp"
#include "PointTree.hpp"
#include "RadialKernel.hpp"

#include <cstdint>
#include <memory>

namespace dcprbf
{

class RbfEvaluator
{
public:
    enum class Method { Auto, Tree, Dense };

    RbfEvaluator(const RadialKernel& kernel, const LinearPolynomial& polynomial);

    //- Set the centres (N x 3), weights (N x 3) and polynomial coefficients
    //  (polynomial.size() x 3, in the constructor's polynomial frame)
    void assign
    (
        const Points& centres,
        const Values& alpha,
        const Eigen::MatrixX3d& beta
    );

    //- Force a method (Tree for a global kernel means Dense)
    void setMethod(Method m) { method_ = m; }

    //- Evaluate at n points x (row-major xyz) into out (row-major), threaded
    void evaluate(const double* x, std::size_t n, double* out) const;

    Values evaluate(const Points& x) const;

    //- evaluate(x, n, out)'s values at the listed points alone, bit for
    //  bit (the method Auto picks for all n points; each point's sums do
    //  not depend on the others): point rows[k] into out's row k
    void evaluateRows
    (
        const double* x,
        std::size_t n,
        const std::vector<int>& rows,
        double* out
    ) const;

    //- The plain double loop over points and centres, one thread: the
    //  reference for tests and benchmarks
    void evaluateBruteForce(const double* x, std::size_t n, double* out) const;

    //- Would Auto use the tree for these points?
    bool usesTree(const double* x, std::size_t n) const;

    std::size_t size() const { return centres_.rows(); }
    const RadialKernel& kernel() const { return kernel_; }
    const Points& centres() const { return centres_; }
    const Values& weights() const { return alpha_; }
    const Eigen::MatrixX3d& polynomialCoeffs() const { return beta_; }
    const LinearPolynomial& polynomial() const { return polynomial_; }

    //- The interpolant's identity: new at every construction and assign()
    //  (unique over all evaluators of the process), kept by a move
    std::uint64_t identity() const { return identity_; }

private:
    void evaluateTree(const double* x, std::size_t n, double* out) const;
    void evaluateDense(const double* x, std::size_t n, double* out) const;

    //- out[d] += p(x)_d
    void addPolynomial(const double* x, double* out) const;

    //- A new identity
    static std::uint64_t nextIdentity();

    RadialKernel kernel_;
    LinearPolynomial polynomial_;
    Method method_;
    std::uint64_t identity_;

    Points centres_;
    Values alpha_;
    Eigen::MatrixX3d beta_;

    // Dense path: centres and weights, one array per component
    Eigen::ArrayXd cx_, cy_, cz_, ax_, ay_, az_;

    // Tree path (compact kernels)
    std::unique_ptr<PointTree> tree_;
};

} // namespace dcprbf
