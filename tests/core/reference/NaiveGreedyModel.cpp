// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "NaiveGreedyModel.hpp"
#include "RbfEvaluator.hpp"
#include "SaddleSolver.hpp"

namespace dcprbf
{

NaiveGreedyModel::NaiveGreedyModel
(
    const RadialKernel& kernel,
    const LinearPolynomial& polynomial,
    const Points& candidates,
    const Values& displacements
)
:
    kernel_(kernel),
    polynomial_(polynomial),
    x_(candidates),
    d_(displacements),
    residual_(displacements)
{}


void NaiveGreedyModel::add(const std::vector<Eigen::Index>& indices)
{
    selected_.insert(selected_.end(), indices.begin(), indices.end());
    const Eigen::Index n = selected_.size();
    Points c(n, 3);
    Values dc(n, 3);
    for (Eigen::Index j = 0; j < n; ++j)
    {
        c.row(j) = x_.row(selected_[j]);
        dc.row(j) = d_.row(selected_[j]);
    }
    Eigen::MatrixXd phi(n, n);
    kernel_.visit([&](const auto& k)
    {
        #pragma omp parallel for schedule(static)
        for (Eigen::Index j = 0; j < n; ++j)
        {
            for (Eigen::Index i = 0; i < n; ++i)
            {
                phi(i, j) = k((c.row(i) - c.row(j)).norm());
            }
        }
    });
    const SaddleSolver solver(phi, polynomial_.basis(c), kernel_.positiveDefinite());
    solver.solve(dc, alpha_, beta_);

    RbfEvaluator evaluator(kernel_, polynomial_);
    evaluator.assign(c, alpha_, beta_);
    residual_ = d_ - evaluator.evaluate(x_);
}


void NaiveGreedyModel::coefficients(Values& alpha, Eigen::MatrixX3d& beta) const
{
    alpha = alpha_;
    beta = beta_;
}


GreedyResult selectNaive
(
    const GreedySelector& selector,
    const Points& candidates,
    const Values& displacements
)
{
    return selector.run
    (
        [](const RadialKernel& kernel, const LinearPolynomial& frame,
           const Points& x, const Values& d)
        {
            return std::unique_ptr<GreedyModel>(new NaiveGreedyModel(kernel, frame, x, d));
        },
        candidates,
        displacements
    );
}

} // namespace dcprbf
