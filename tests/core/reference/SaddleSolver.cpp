// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "SaddleSolver.hpp"

#include <sstream>

namespace dcprbf
{

SaddleSolver::SaddleSolver
(
    const Eigen::MatrixXd& phi,
    const Eigen::MatrixXd& poly,
    bool positiveDefinite
)
:
    n_(phi.rows()),
    m_(poly.cols()),
    cholesky_(positiveDefinite)
{
    if (cholesky_)
    {
        phiLLT_.compute(phi);
        if (phiLLT_.info() != Eigen::Success)
        {
            throw Error
            (
                "the kernel matrix is not positive definite: control points"
                " closer than round-off allows, or a kernel/radius unfit for"
                " this point set"
            );
        }
        if (m_ > 0)
        {
            W_ = phiLLT_.matrixL().solve(poly);
            schurLLT_.compute(W_.transpose()*W_);
            if (schurLLT_.info() != Eigen::Success)
            {
                throw Error
                (
                    "the control points cannot carry the linear polynomial"
                    " (collinear in 2D, coplanar in 3D)"
                );
            }
        }
        return;
    }

    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n_ + m_, n_ + m_);
    A.topLeftCorner(n_, n_) = phi;
    A.topRightCorner(n_, m_) = poly;
    A.bottomLeftCorner(m_, n_) = poly.transpose();
    lu_.compute(A);
    const double rc = lu_.rcond();
    if (!(rc > 1e-15))
    {
        std::ostringstream os;
        os  << "the RBF system is singular (reciprocal condition number "
            << rc << "): duplicate control points or a point set that cannot"
            << " carry the polynomial";
        throw Error(os.str());
    }
}


void SaddleSolver::solve
(
    const Values& rhs,
    Values& alpha,
    Eigen::MatrixX3d& beta
) const
{
    if (rhs.rows() != n_)
    {
        throw Error("right-hand side size differs from the number of centres");
    }
    if (cholesky_)
    {
        Eigen::MatrixX3d y = phiLLT_.matrixL().solve(Eigen::MatrixX3d(rhs));
        if (m_ > 0)
        {
            beta = schurLLT_.solve(W_.transpose()*y);
            y -= W_*beta;
        }
        else
        {
            beta.resize(0, 3);
        }
        alpha = phiLLT_.matrixU().solve(y);
        return;
    }

    Eigen::MatrixX3d b = Eigen::MatrixX3d::Zero(n_ + m_, 3);
    b.topRows(n_) = rhs;
    const Eigen::MatrixX3d x = lu_.solve(b);
    alpha = x.topRows(n_);
    beta = x.bottomRows(m_);
}

} // namespace dcprbf
