// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "SaddleFactorization.hpp"

#include <algorithm>
#include <cmath>

namespace dcprbf
{

SaddleFactorization::SaddleFactorization
(
    const RadialKernel& kernel,
    const LinearPolynomial& polynomial
)
:
    kernel_(kernel, polynomial),
    n_(0),
    factorizations_(0)
{}


void SaddleFactorization::reserve(Eigen::Index n)
{
    if (n <= centres_.rows()) return;
    const Eigen::Index cap = std::max<Eigen::Index>({n, 2*centres_.rows(), 16});
    centres_.conservativeResize(cap, 3);
    W_.conservativeResize(cap, polynomial().size());
    if (refines()) phi_.conservativeResize(cap, cap);
}


void SaddleFactorization::factorize(const Points& centres)
{
    kernel_ = AugmentedKernel(kernel_.kernel(), polynomial());
    factorizeWithCurrentShift(centres);
}


void SaddleFactorization::raiseShiftAndFactorize(const Points& centres)
{
    kernel_.increaseShift();
    factorizeWithCurrentShift(centres);
}


void SaddleFactorization::factorizeWithCurrentShift(const Points& c)
{
    n_ = 0;
    L_.clear();
    const Eigen::Index n = c.rows();
    const Eigen::MatrixXd phi = kernel_.radialMatrix(c, c);
    const Eigen::MatrixXd P = polynomial().basis(c);
    for (;;)
    {
        Eigen::LLT<Eigen::MatrixXd> llt
        (
            kernel_.shift() > 0 ? phi + kernel_.shift()*P*P.transpose() : phi
        );
        ++factorizations_;
        if (llt.info() == Eigen::Success)
        {
            L_.assign(llt.matrixL());
            break;
        }
        kernel_.increaseShift();  // throws unless TPS with room to grow
    }
    reserve(n);
    centres_.topRows(n) = c;
    n_ = n;
    if (refines()) phi_.topLeftCorner(n, n) = phi;
    if (polynomial().enabled())
    {
        auto W = W_.topRows(n);
        W = P;
        L_.solveLowerInPlace(W);
    }
    updateSchur();
}


void SaddleFactorization::updateSchur()
{
    inverseDiagonal_.resize(0);         // (the factorization changed)
    // below m points S is singular by construction: a set being built
    // point by point (greedy seed) gets its S with the m-th point
    if (n_ < polynomial().size()) return;
    const auto W = W_.topRows(n_);
    schur_.compute(W.transpose()*W);
    if (schur_.info() != Eigen::Success)
    {
        throw Error
        (
            "the control points cannot carry the linear polynomial"
            " (collinear in 2D, coplanar in 3D)"
        );
    }
}


double SaddleFactorization::newRow(const double* x, Eigen::VectorXd& l) const
{
    l.resize(n_);
    kernel_.column(centres_.topRows(n_), x, l.data());
    L_.solveLowerInPlace(l);
    return kernel_.diagonal(x) - l.squaredNorm();
}


bool SaddleFactorization::acceptablePivot(const double* x, double pivotSq) const
{
    return pivotSq > 1e-14*std::abs(kernel_.diagonal(x));
}


void SaddleFactorization::append
(
    const double* x,
    const Eigen::VectorXd& l,
    double pivot
)
{
    reserve(n_ + 1);
    centres_.row(n_) << x[0], x[1], x[2];
    if (polynomial().enabled())
    {
        double q[4];
        polynomial().basis(x, q);
        const Eigen::Map<const Eigen::RowVectorXd> qx(q, polynomial().size());
        W_.row(n_) = (qx - l.transpose()*W_.topRows(n_))/pivot;
    }
    if (refines())
    {
        Eigen::VectorXd col(n_ + 1);
        kernel_.radialColumn(centres_.topRows(n_ + 1), x, col.data());
        phi_.col(n_).head(n_ + 1) = col;
        phi_.row(n_).head(n_ + 1) = col.transpose();
    }
    L_.append(l, pivot);
    ++n_;
    updateSchur();
}


void SaddleFactorization::remove(Eigen::Index i)
{
    L_.remove(i, W_);
    for (Eigen::Index j = i; j + 1 < n_; ++j)
    {
        centres_.row(j) = centres_.row(j + 1);
    }
    if (refines())  // delete row and column i of Phi
    {
        for (Eigen::Index j = 0; j < n_; ++j)
        {
            double* col = phi_.col(j).data();
            std::copy(col + i + 1, col + n_, col + i);
            if (j > i) std::copy(col, col + n_ - 1, phi_.col(j - 1).data());
        }
    }
    --n_;
    updateSchur();
}


void SaddleFactorization::solve
(
    const Values& values,
    Values& alpha,
    Eigen::MatrixX3d& beta
) const
{
    const Eigen::Index m = polynomial().size();
    Eigen::MatrixX3d a, b;
    solveFactored(values, Eigen::MatrixX3d::Zero(m, 3), a, b);
    if (refines())
    {
        // Phi_c da + P db' = r, P^T da = s  <=>  Phi da + P (db' + c s) = r
        const auto phi = phi_.topLeftCorner(n_, n_);
        const Eigen::MatrixXd P = polynomial().basis(centres());
        for (int step = 0; step < 2; ++step)
        {
            const Eigen::MatrixX3d r = Eigen::MatrixX3d(values) - phi*a - P*b;
            const Eigen::MatrixX3d s = -P.transpose()*a;
            Eigen::MatrixX3d da, db;
            solveFactored(r, s, da, db);
            a += da;
            b += db + kernel_.shift()*s;
        }
    }
    alpha = a;
    beta = b;
}


void SaddleFactorization::solveFactored
(
    const Eigen::MatrixX3d& r,
    const Eigen::MatrixX3d& s,
    Eigen::MatrixX3d& alpha,
    Eigen::MatrixX3d& beta
) const
{
    // y = L^{-1} r, beta = S^{-1} (W^T y - s), alpha = L^{-T} (y - W beta)
    Eigen::MatrixX3d y = r;
    L_.solveLowerInPlace(y);
    if (polynomial().enabled())
    {
        const auto W = W_.topRows(n_);
        beta = schur_.solve(W.transpose()*y - s);
        y.noalias() -= W*beta;
    }
    else
    {
        beta.resize(0, 3);
    }
    L_.solveUpperInPlace(y);
    alpha = y;
}

const Eigen::VectorXd& SaddleFactorization::inverseDiagonal() const
{
    if (inverseDiagonal_.size() == n_ && n_ > 0)
    {
        return inverseDiagonal_;
    }
    // Z = L^{-1}, lower triangular: each block of columns from its own
    // diagonal down (N^3/6 flops, not the N^3/2 of a solve with the whole
    // identity; N = 289: 1.2 -> 0.5 ms)
    constexpr Eigen::Index block = 32;
    Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(n_, n_);
    const auto L = L_.matrixL();
    for (Eigen::Index j0 = 0; j0 < n_; j0 += block)
    {
        const Eigen::Index jb = std::min(block, n_ - j0), m = n_ - j0;
        auto Zb = Z.block(j0, j0, m, jb);
        Zb.topRows(jb).setIdentity();
        L.block(j0, j0, m, m).triangularView<Eigen::Lower>().solveInPlace(Zb);
    }
    Eigen::VectorXd b = Z.colwise().squaredNorm().transpose();
    if (W_.cols() > 0 && n_ > 0)
    {
        Eigen::MatrixXd T = W().transpose()*Z;          // m x N
        schur_.matrixL().solveInPlace(T);               // R^{-T} W^T Z
        b -= T.colwise().squaredNorm().transpose();
    }
    inverseDiagonal_ = std::move(b);
    return inverseDiagonal_;
}


} // namespace dcprbf
