// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// DynamicControlSet, continued: the pieces of the error-guided swaps (state
// and undo, leave-one-out errors, the join and leave choices, the
// constant-size swap, the blended interpolant).
#include "DynamicControlSet.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace dcprbf
{

DynamicControlSet::State DynamicControlSet::freshState
(
    const std::vector<Eigen::Index>& indices,
    const std::vector<int>& ages
) const
{
    Points c(indices.size(), 3);
    for (std::size_t k = 0; k < indices.size(); ++k)
    {
        if (indices[k] < 0 || indices[k] >= candidates_.rows())
        {
            throw Error("control point index out of range");
        }
        c.row(k) = candidates_.row(indices[k]);
    }
    IncrementalSaddleSolver s(solver_.kernel(), solver_.polynomial());
    s.reset(c);
    return State{s, indices, ages};
}


void DynamicControlSet::restore(const State& s)
{
    solver_ = s.solver;
    indices_ = s.indices;
    age_ = s.ages;
    std::fill(inSet_.begin(), inSet_.end(), 0);
    for (const Eigen::Index i : indices_) inSet_[i] = 1;
}


Values DynamicControlSet::leaveOneOutErrors(const Values& candidateValues) const
{
    Values v(indices_.size(), 3);
    for (std::size_t k = 0; k < indices_.size(); ++k)
    {
        v.row(k) = candidateValues.row(indices_[k]);
    }
    Values alpha;
    Eigen::MatrixX3d beta;
    solver_.solve(v, alpha, beta);
    const Eigen::VectorXd& b = solver_.factorization().inverseDiagonal();
    // B_jj vanishes (to round-off) for a centre the polynomial needs: for
    // every centre where there are no more of them than the polynomial's
    // terms (B = 0), else where it is round-off of the largest
    const bool allNeeded = b.size() <= Eigen::Index(solver_.polynomial().size());
    const double tiny = 1e-10*(b.size() ? b.cwiseAbs().maxCoeff() : 0.0);
    Values errors(alpha.rows(), 3);
    for (Eigen::Index k = 0; k < alpha.rows(); ++k)
    {
        if (!allNeeded && std::abs(b(k)) > tiny)
        {
            errors.row(k) = alpha.row(k)/b(k);
        }
        else
        {
            errors.row(k).setConstant(std::numeric_limits<double>::infinity());
        }
    }
    return errors;
}


Eigen::Index DynamicControlSet::mostInaccurateNear
(
    const Eigen::RowVector3d& x,
    const Values& candidateValues,
    int k,
    double floor
) const
{
    if (candidateValues.rows() != candidates_.rows())
    {
        throw Error("mostInaccurateNear: values must be given at every candidate");
    }
    std::vector<Eigen::Index> all(candidates_.rows());
    std::iota(all.begin(), all.end(), 0);
    std::vector<Eigen::Index> near =
        nearestFirst(x, all, [&](Eigen::Index j) { return !inSet_[j]; });
    near.resize(std::min(near.size(), std::size_t(std::max(k, 0))));
    // the interpolant at those candidates alone
    Points at(near.size(), 3);
    for (std::size_t r = 0; r < near.size(); ++r) at.row(r) = candidates_.row(near[r]);
    const Values s = evaluator_.evaluate(at);
    Eigen::Index best = -1;
    double bestScore = 0;
    for (std::size_t r = 0; r < near.size(); ++r)
    {
        const double e = (candidateValues.row(near[r]) - s.row(r)).norm();
        const double d = (candidates_.row(near[r]) - x).norm();
        const double score = e/std::max(d, 1e-300);
        if (e > floor && score > bestScore)
        {
            bestScore = score;
            best = near[r];
        }
    }
    return best;
}


std::vector<Eigen::Index> DynamicControlSet::removalOrder(const Values& looErrors) const
{
    std::vector<std::pair<double, Eigen::Index>> order;
    for (std::size_t k = 0; k < indices_.size(); ++k)
    {
        if
        (
            removable_[indices_[k]] && age_[k] >= options_.protectSteps
         && std::isfinite(looErrors(Eigen::Index(k), 0))
        )
        {
            order.emplace_back(looErrors.row(k).norm(), indices_[k]);
        }
    }
    std::sort(order.begin(), order.end());
    std::vector<Eigen::Index> out;
    for (const auto& o : order) out.push_back(o.second);
    return out;
}


bool DynamicControlSet::swap(Eigen::Index in, Eigen::Index out)
{
    if (in < 0 || in >= candidates_.rows() || inSet_[in] || out < 0 || !inSet_[out])
    {
        throw Error("swap: the joining point must be a candidate outside the set"
            " and the leaving one a control point");
    }
    const auto k = std::find(indices_.begin(), indices_.end(), out) - indices_.begin();
    try
    {
        solver_.replace(k, candidates_.row(in));
    }
    catch (const Error&)
    {
        return false;
    }
    indices_.erase(indices_.begin() + k);
    age_.erase(age_.begin() + k);
    inSet_[out] = 0;
    indices_.push_back(in);
    age_.push_back(0);
    inSet_[in] = 1;
    return true;
}


void DynamicControlSet::solveBlended
(
    const Values& candidateValues,
    const State& from,
    double w
)
{
    const auto solveOn = [&](const IncrementalSaddleSolver& s,
        const std::vector<Eigen::Index>& idx, Values& alpha, Eigen::MatrixX3d& beta)
    {
        Values v(idx.size(), 3);
        for (std::size_t k = 0; k < idx.size(); ++k) v.row(k) = candidateValues.row(idx[k]);
        s.solve(v, alpha, beta);
    };
    Values a1, a0;
    Eigen::MatrixX3d b1, b0;
    solveOn(solver_, indices_, a1, b1);
    solveOn(from.solver, from.indices, a0, b0);

    // centres of both sets, merged by candidate index
    std::vector<Eigen::Index> row(candidates_.rows(), -1);
    std::vector<Eigen::Index> merged;
    const std::vector<Eigen::Index>* sets[] = {&indices_, &from.indices};
    for (const std::vector<Eigen::Index>* idx : sets)
    {
        for (const Eigen::Index i : *idx)
        {
            if (row[i] < 0)
            {
                row[i] = Eigen::Index(merged.size());
                merged.push_back(i);
            }
        }
    }
    Points c(merged.size(), 3);
    Values alpha = Values::Zero(merged.size(), 3);
    for (std::size_t r = 0; r < merged.size(); ++r) c.row(r) = candidates_.row(merged[r]);
    for (std::size_t k = 0; k < indices_.size(); ++k) alpha.row(row[indices_[k]]) += w*a1.row(k);
    for (std::size_t k = 0; k < from.indices.size(); ++k)
    {
        alpha.row(row[from.indices[k]]) += (1 - w)*a0.row(k);
    }
    evaluator_.assign(c, alpha, w*b1 + (1 - w)*b0);
}


} // namespace dcprbf
