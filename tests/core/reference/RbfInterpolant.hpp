// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF test reference (not in libdcpRBF): RBF interpolant of a vector
// field (paper eqs. 2-6), solved densely from scratch (SaddleSolver)
//
//     s(x) = sum_j alpha_j phi(|x - c_j|) + p(x),
//     p(x) = beta_0 + sum_k beta_k (x_k - shift_k)/scale   (k < dim)
//
// with the constraints sum_j alpha_j q(c_j) = 0 for every linear q. The
// polynomial coordinates are shifted to the centroid and scaled by the extent
// of the centres for conditioning. In 2D (dim = 2) the points' z must be 0
// (the caller projects onto the plane).
//
// Polynomial frame: LinearPolynomial::boundingBox of the centres. Evaluation:
// RbfEvaluator (kd-tree for compact kernels, blocked dense otherwise).
//
// Usage:
//     RbfInterpolant s(RadialKernel::fromName("WendlandC2", 0.5), true, 3);
//     s.setCentres(centres);   // checks and factorizes (throws Error if ill-posed)
//     s.solve(displacements);  // O(N^2) per right-hand side
//     Values d = s.evaluate(volumePoints);
#pragma once

#include "LinearPolynomial.hpp"
#include "RadialKernel.hpp"
#include "RbfEvaluator.hpp"
#include "SaddleSolver.hpp"

#include <memory>

namespace dcprbf
{

class RbfInterpolant
{
public:
    RbfInterpolant(const RadialKernel& kernel, bool polynomial, int dim);

    //- Check the centres (count, finite, distinct, polynomial solvable) and
    //  factorize. Throws Error naming the problem.
    void setCentres(const Points& centres);

    //- Coefficients for these values at the centres (setCentres first)
    void solve(const Values& values);

    //- setCentres then solve
    void fit(const Points& centres, const Values& values)
    {
        setCentres(centres);
        solve(values);
    }

    //- Evaluate at n points x (row-major xyz) into out (row-major), threaded
    void evaluate(const double* x, std::size_t n, double* out) const;

    Values evaluate(const Points& x) const;

    // Access
    const RadialKernel& kernel() const { return kernel_; }
    bool polynomial() const { return polynomial_; }
    int dim() const { return dim_; }
    std::size_t size() const { return centres_.rows(); }
    const Points& centres() const { return centres_; }
    const Values& weights() const { return alpha_; }
    const Eigen::MatrixX3d& polynomialCoeffs() const { return beta_; }

    //- The frame polynomialCoeffs() are written in (bounding box of the
    //  centres)
    const LinearPolynomial& polynomialFrame() const { return frame_; }

    //- The evaluator holding the current coefficients (after solve)
    const RbfEvaluator& evaluator() const { return evaluator_; }

    //- Polynomial basis (1, scaled coordinates) at the rows of x: n x (dim+1)
    Eigen::MatrixXd polynomialBasis(const Points& x) const;

    //- Kernel matrix between the rows of a and b
    Eigen::MatrixXd kernelMatrix(const Points& a, const Points& b) const;

private:
    RadialKernel kernel_;
    bool polynomial_;
    int dim_;

    Points centres_;
    LinearPolynomial frame_;
    std::unique_ptr<SaddleSolver> solver_;
    Values alpha_;
    Eigen::MatrixX3d beta_;
    RbfEvaluator evaluator_;
};

} // namespace dcprbf
