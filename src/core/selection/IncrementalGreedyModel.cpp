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
    IncrementalGreedyModel(kernel, polynomial, CandidateRows(candidates, displacements))
{}


IncrementalGreedyModel::IncrementalGreedyModel
(
    const RadialKernel& kernel,
    const LinearPolynomial& polynomial,
    const CandidateRows& rows
)
:
    rows_(rows),
    f_(new SaddleFactorization(kernel, polynomial)),
    a_(Eigen::MatrixX3d::Zero(rows.size(), 3)),
    Q_(polynomial.basis(rows.points())),
    WTy_(Eigen::MatrixX3d::Zero(polynomial.size(), 3)),
    residual_(rows.values())
{}


void IncrementalGreedyModel::reserve(Eigen::Index n)
{
    if (n <= V_.cols()) return;
    const Eigen::Index cap = std::max<Eigen::Index>({n, 2*V_.cols(), 64});
    V_.conservativeResize(rows_.size(), cap);
    y_.conservativeResize(cap, 3);
    dSelected_.conservativeResize(cap, 3);
}


void IncrementalGreedyModel::add(const std::vector<Eigen::Index>& indices)
{
    for (const Eigen::Index c : indices) append(c);
    updateResidual();
}


void IncrementalGreedyModel::append(Eigen::Index c)
{
    const Eigen::Index n = f_->size();
    const Eigen::Index nb = rows_.size();
    reserve(n + 1);

    // The candidate's coordinates, displacement and l = v(c), its row of the
    // Newton basis, from the rank holding it
    const Eigen::Index lc = rows_.local(c);
    const Eigen::VectorXd own =
        lc >= 0 ? Eigen::VectorXd(V_.row(lc).head(n).transpose()) : Eigen::VectorXd();
    Eigen::VectorXd fetched(6 + n);
    rows_.fetch(c, own.data(), n, fetched.data());
    Points xc(1, 3);
    xc << fetched(0), fetched(1), fetched(2);
    const Eigen::RowVector3d dc(fetched(3), fetched(4), fetched(5));
    const Eigen::VectorXd l = fetched.tail(n);

    Eigen::VectorXd k(nb);
    f_->kernel().column(rows_.points(), xc.data(), k.data());
    double kcc = 0;
    f_->kernel().column(xc, xc.data(), &kcc);
    const double pivotSq = kcc - l.squaredNorm();
    dSelected_.row(n) = dc;
    if (!f_->acceptablePivot(xc.data(), pivotSq))
    {
        if (f_->kernel().kernel().positiveDefinite())
        {
            std::ostringstream os;
            os  << "candidate point " << c << " at (" << xc << ") is"
                << " numerically dependent on the " << n << " selected points"
                << " (kernel matrix singular to round-off)";
            throw Error(os.str());
        }
        selected_.push_back(c);
        Points centres(n + 1, 3);
        centres.topRows(n) = f_->centres();
        centres.row(n) = xc;
        raiseShiftAndRebuild(centres);
        return;
    }
    const double pivot = std::sqrt(pivotSq);
    f_->append(xc.data(), l, pivot);
    selected_.push_back(c);

    const Eigen::RowVector3d yNew = (dc - l.transpose()*y_.topRows(n))/pivot;
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
    if (lc >= 0) V_(lc, n) = pivot;
}


void IncrementalGreedyModel::updateResidual()
{
    if (f_->size() < f_->polynomial().size())
    {
        throw Error("greedy seed too small to carry the polynomial");
    }
    residual_ = rows_.values() - a_;
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
    V = f_->kernel().matrix(rows_.points(), f_->centres());
    f_->factor().solveRightUpperInPlace(V);
    auto y = y_.topRows(n);
    y = dSelected_.topRows(n);
    f_->factor().solveLowerInPlace(y);
    a_.noalias() = V*y;
    Q_ = f_->polynomial().basis(rows_.points());
    if (f_->polynomial().enabled())
    {
        Q_.noalias() -= V*f_->W();
        WTy_.noalias() = f_->W().transpose()*y;
    }
    if (n >= f_->polynomial().size()) updateResidual();
}


void IncrementalGreedyModel::raiseShiftAndRebuild()
{
    raiseShiftAndRebuild(f_->centres());
}


void IncrementalGreedyModel::raiseShiftAndRebuild(const Points& centres)
{
    f_->raiseShiftAndFactorize(centres);
    rebuild();
}


void IncrementalGreedyModel::coefficients
(
    Values& alpha,
    Eigen::MatrixX3d& beta
) const
{
    const Values dc = dSelected_.topRows(f_->size());
    f_->solve(dc, alpha, beta);
}

} // namespace dcprbf
