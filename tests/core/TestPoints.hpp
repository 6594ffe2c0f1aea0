// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Point sets shared by the core unit tests.
#pragma once

#include "LinearPolynomial.hpp"
#include "RadialKernel.hpp"
#include "SaddleSolver.hpp"
#include "Types.hpp"

#include <cmath>
#include <random>

namespace dcprbf
{
namespace test
{

//- n pseudo-random points in the box [0, L]^3 (z = 0 when dim = 2)
inline Points randomPoints(int n, int dim, unsigned seed, double L = 1.0)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(0.0, L);
    Points p(n, 3);
    for (int i = 0; i < n; ++i)
    {
        p(i, 0) = u(gen);
        p(i, 1) = u(gen);
        p(i, 2) = dim == 3 ? u(gen) : 0.0;
    }
    return p;
}

//- A smooth non-polynomial vector field
inline Values smoothField(const Points& p)
{
    Values v(p.rows(), 3);
    for (Eigen::Index i = 0; i < p.rows(); ++i)
    {
        v(i, 0) = std::sin(3*p(i, 0)) + p(i, 1)*p(i, 1);
        v(i, 1) = std::cos(2*p(i, 1))*p(i, 0);
        v(i, 2) = std::exp(-p(i, 0)) - p(i, 2);
    }
    return v;
}

//- An affine map A x + b: rotation, stretch and translation
inline Values affineField(const Points& p, int dim)
{
    Eigen::Matrix3d A;
    A << 0.10, -0.30, 0.05,
         0.25,  0.20, -0.10,
        -0.05,  0.15, 0.30;
    Eigen::RowVector3d b(0.4, -0.2, 0.7);
    if (dim == 2)
    {
        A.row(2).setZero();
        A.col(2).setZero();
        b(2) = 0;
    }
    return (p*A.transpose()).rowwise() + b;
}

//- Kernel matrix phi(|a_i - b_j|), straightforward loops
inline Eigen::MatrixXd kernelMatrix
(
    const RadialKernel& k,
    const Points& a,
    const Points& b
)
{
    Eigen::MatrixXd K(a.rows(), b.rows());
    for (Eigen::Index i = 0; i < a.rows(); ++i)
    {
        for (Eigen::Index j = 0; j < b.rows(); ++j)
        {
            K(i, j) = k((a.row(i) - b.row(j)).norm());
        }
    }
    return K;
}

//- Solve the saddle system from scratch (SaddleSolver) in a given frame
inline void freshSolve
(
    const RadialKernel& k,
    const LinearPolynomial& frame,
    const Points& centres,
    const Values& values,
    Values& alpha,
    Eigen::MatrixX3d& beta
)
{
    SaddleSolver s
    (
        kernelMatrix(k, centres, centres), frame.basis(centres),
        k.positiveDefinite()
    );
    s.solve(values, alpha, beta);
}

//- max |a - b| / max |b| (0 for an empty b)
template<class A, class B>
double relDiff(const A& a, const B& b)
{
    if (b.size() == 0) return a.size() == 0 ? 0.0 : 1.0;
    const double scale = b.cwiseAbs().maxCoeff();
    return (a - b).cwiseAbs().maxCoeff()/(scale > 0 ? scale : 1.0);
}

//- Shape lengths used by the tests: support radius for the compact kernels,
//  shorter lengths for the global ones to keep the systems well conditioned
inline double testRadius(const std::string& name, double compactRadius = 0.6)
{
    if (name == "Gaussian" || name == "IMQ") return 0.1;
    if (name == "TPS") return 1.0;
    return compactRadius;
}

} // namespace test
} // namespace dcprbf
