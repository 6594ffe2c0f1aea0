// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "IncrementalGreedyModel.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cmath>
#include <sstream>

namespace dcprbf
{

IncrementalGreedyModel::IncrementalGreedyModel
(
    const RadialKernel& kernel,
    const LinearPolynomial& polynomial,
    const Points& candidates,
    const Values& displacements
)
:
    x_(candidates),
    d_(displacements),
    f_(new SaddleFactorization(kernel, polynomial)),
    a_(Eigen::MatrixX3d::Zero(candidates.rows(), 3)),
    Q_(polynomial.basis(candidates)),
    WTy_(Eigen::MatrixX3d::Zero(polynomial.size(), 3)),
    residual_(displacements)
{}


void IncrementalGreedyModel::reserve(Eigen::Index n)
{
    if (n <= V_.cols()) return;
    const Eigen::Index cap = std::max<Eigen::Index>({n, 2*V_.cols(), 64});
    V_.conservativeResize(x_.rows(), cap);
    y_.conservativeResize(cap, 3);
}


void IncrementalGreedyModel::add(const std::vector<Eigen::Index>& indices)
{
    for (const Eigen::Index c : indices) append(c);
    updateResidual();
}


void IncrementalGreedyModel::append(Eigen::Index c)
{
    const Eigen::Index n = f_->size();
    const Eigen::Index nb = x_.rows();
    const double* xc = x_.row(c).data();
    reserve(n + 1);

    // l = v(c): the candidate's row of the Newton basis
    const Eigen::VectorXd l = V_.row(c).head(n).transpose();
    Eigen::VectorXd k(nb);
    f_->kernel().column(x_, xc, k.data());
    const double pivotSq = k(c) - l.squaredNorm();
    if (!f_->acceptablePivot(xc, pivotSq))
    {
        if (f_->kernel().kernel().positiveDefinite())
        {
            std::ostringstream os;
            os  << "candidate point " << c << " at (" << x_.row(c) << ") is"
                << " numerically dependent on the " << n << " selected points"
                << " (kernel matrix singular to round-off)";
            throw Error(os.str());
        }
        selected_.push_back(c);
        raiseShiftAndRebuild();
        return;
    }
    const double pivot = std::sqrt(pivotSq);
    f_->append(xc, l, pivot);
    selected_.push_back(c);

    const Eigen::RowVector3d yNew = (d_.row(c) - l.transpose()*y_.topRows(n))/pivot;
    y_.row(n) = yNew;
    const int m = f_->polynomial().size();
    const Eigen::RowVectorXd wNew = f_->W().row(n);
    if (m > 0) WTy_ += wNew.transpose()*yNew;

    // v_new = (k - V l)/pivot, a += v_new y_new, Q -= v_new w_new, by row
    // blocks: one pass over V, split between the threads (when it is worth
    // a parallel region: small problems stay serial)
    #pragma omp parallel if(nb*(n + 1) > 100000)
    {
        int nt = 1, t = 0;
        #ifdef _OPENMP
        nt = omp_get_num_threads();
        t = omp_get_thread_num();
        #endif
        const Eigen::Index b = nb*t/nt;
        const Eigen::Index e = nb*(t + 1)/nt;
        auto v = V_.col(n).segment(b, e - b);
        v = k.segment(b, e - b);
        v.noalias() -= V_.block(b, 0, e - b, n)*l;
        v /= pivot;
        a_.middleRows(b, e - b).noalias() += v*yNew;
        if (m > 0) Q_.middleRows(b, e - b).noalias() -= v*wNew;
    }
    V_(c, n) = pivot;
}


void IncrementalGreedyModel::updateResidual()
{
    if (f_->size() < f_->polynomial().size())
    {
        throw Error("greedy seed too small to carry the polynomial");
    }
    residual_ = d_ - a_;
    if (f_->polynomial().enabled())
    {
        residual_ -= Q_*f_->schurSolve(WTy_);
    }
}


void IncrementalGreedyModel::rebuild()
{
    const Eigen::Index n = f_->size();
    reserve(n);
    // V = K_c(X, C) L^{-T}
    auto V = V_.leftCols(n);
    V = f_->kernel().matrix(x_, f_->centres());
    f_->factor().solveRightUpperInPlace(V);
    auto y = y_.topRows(n);
    for (Eigen::Index j = 0; j < n; ++j) y.row(j) = d_.row(selected_[j]);
    f_->factor().solveLowerInPlace(y);
    a_.noalias() = V*y;
    Q_ = f_->polynomial().basis(x_);
    if (f_->polynomial().enabled())
    {
        Q_.noalias() -= V*f_->W();
        WTy_.noalias() = f_->W().transpose()*y;
    }
    if (n >= f_->polynomial().size()) updateResidual();
}


void IncrementalGreedyModel::raiseShiftAndRebuild()
{
    Points c(selected_.size(), 3);
    for (std::size_t j = 0; j < selected_.size(); ++j) c.row(j) = x_.row(selected_[j]);
    f_->raiseShiftAndFactorize(c);
    rebuild();
}


void IncrementalGreedyModel::coefficients
(
    Values& alpha,
    Eigen::MatrixX3d& beta
) const
{
    Values dc(selected_.size(), 3);
    for (std::size_t j = 0; j < selected_.size(); ++j) dc.row(j) = d_.row(selected_[j]);
    f_->solve(dc, alpha, beta);
}

} // namespace dcprbf
