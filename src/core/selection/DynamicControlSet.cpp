// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "DynamicControlSet.hpp"

#include <algorithm>
#include <numeric>

namespace dcprbf
{

DynamicControlSet::DynamicControlSet
(
    const Points& candidates,
    const std::vector<char>& removable,
    const RadialKernel& kernel,
    bool polynomial,
    int dim,
    const Options& options
)
:
    candidates_(candidates),
    removable_(removable),
    options_(options),
    solver_(kernel, LinearPolynomial::boundingBox(polynomial, dim, candidates)),
    evaluator_(kernel, solver_.polynomial()),
    inSet_(candidates.rows(), 0)
{
    if (Eigen::Index(removable_.size()) != candidates_.rows())
    {
        throw Error("removable flags and candidates differ in number");
    }
    if (options_.minPoints > options_.maxPoints)
    {
        throw Error("minPoints exceeds maxPoints");
    }
}


void DynamicControlSet::reset(const std::vector<Eigen::Index>& indices)
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
    solver_.reset(c);
    setIndices(indices);
}


void DynamicControlSet::reset
(
    const std::vector<Eigen::Index>& indices,
    SaddleFactorization factorization
)
{
    if (factorization.size() != Eigen::Index(indices.size()))
    {
        throw Error("control set: the factorization does not match the indices");
    }
    for (const Eigen::Index i : indices)
    {
        if (i < 0 || i >= candidates_.rows())
        {
            throw Error("control point index out of range");
        }
    }
    solver_ = IncrementalSaddleSolver(std::move(factorization));
    setIndices(indices);
}


void DynamicControlSet::refactorize()
{
    const std::vector<int> ages(age_);
    reset(std::vector<Eigen::Index>(indices_));
    age_ = ages;
}


void DynamicControlSet::setIndices(const std::vector<Eigen::Index>& indices)
{
    indices_ = indices;
    std::fill(inSet_.begin(), inSet_.end(), 0);
    for (const Eigen::Index i : indices_) inSet_[i] = 1;
    age_.assign(indices_.size(), options_.protectSteps);
}




bool DynamicControlSet::add(Eigen::Index i)
{
    if (i < 0 || i >= candidates_.rows() || inSet_[i])
    {
        throw Error("candidate index out of range or already a control point");
    }
    if (size() >= options_.maxPoints) return false;
    solver_.add(candidates_.row(i));
    indices_.push_back(i);
    inSet_[i] = 1;
    age_.push_back(0);
    return true;
}


void DynamicControlSet::setAges(const std::vector<int>& ages)
{
    if (ages.size() != indices_.size())
    {
        throw Error("one age per control point is needed");
    }
    age_ = ages;
}


Eigen::Index DynamicControlSet::addNearest(const Eigen::RowVector3d& x)
{
    if (size() >= options_.maxPoints) return -1;
    std::vector<Eigen::Index> all(candidates_.rows());
    std::iota(all.begin(), all.end(), 0);
    for (const Eigen::Index i : nearestFirst(x, all, [&](Eigen::Index j) { return !inSet_[j]; }))
    {
        try
        {
            add(i);
        }
        catch (const Error&)
        {
            continue;   // numerically dependent on the set: try the next
        }
        return i;
    }
    return -1;
}


Eigen::Index DynamicControlSet::removeNearest(const Eigen::RowVector3d& x)
{
    if (size() <= std::max(options_.minPoints, solver_.minimumSize())) return -1;
    // candidates ordered by distance, among the removable, old-enough centres
    std::vector<Eigen::Index> members(indices_.begin(), indices_.end());
    std::vector<Eigen::Index> ageOf(candidates_.rows(), -1);
    for (std::size_t k = 0; k < indices_.size(); ++k) ageOf[indices_[k]] = age_[k];
    const auto ok = [&](Eigen::Index j)
    {
        return removable_[j] && ageOf[j] >= options_.protectSteps;
    };
    for (const Eigen::Index i : nearestFirst(x, members, ok))
    {
        const auto k = std::find(indices_.begin(), indices_.end(), i) - indices_.begin();
        try
        {
            solver_.remove(k);
        }
        catch (const Error&)
        {
            continue;   // would break polynomial solvability: try the next
        }
        indices_.erase(indices_.begin() + k);
        age_.erase(age_.begin() + k);
        inSet_[i] = 0;
        return i;
    }
    return -1;
}


bool DynamicControlSet::swapNearest
(
    const Eigen::RowVector3d& join,
    const Eigen::RowVector3d& leave
)
{
    std::vector<Eigen::Index> all(candidates_.rows());
    std::iota(all.begin(), all.end(), 0);
    const std::vector<Eigen::Index> in =
        nearestFirst(join, all, [&](Eigen::Index j) { return !inSet_[j]; });
    std::vector<Eigen::Index> members(indices_.begin(), indices_.end());
    std::vector<Eigen::Index> ageOf(candidates_.rows(), -1);
    for (std::size_t k = 0; k < indices_.size(); ++k) ageOf[indices_[k]] = age_[k];
    const std::vector<Eigen::Index> out = nearestFirst(leave, members, [&](Eigen::Index j)
    {
        return removable_[j] && ageOf[j] >= options_.protectSteps;
    });
    for (std::size_t a = 0; a < in.size() && a < std::size_t(options_.maxTries); ++a)
    {
        for (std::size_t r = 0; r < out.size() && r < std::size_t(options_.maxTries); ++r)
        {
            if (swap(in[a], out[r])) return true;
        }
    }
    return false;
}


void DynamicControlSet::nextStep()
{
    for (int& a : age_) ++a;
}


void DynamicControlSet::solve(const Values& candidateValues)
{
    if (candidateValues.rows() != candidates_.rows())
    {
        throw Error("values must be given at every candidate");
    }
    Values v(indices_.size(), 3);
    for (std::size_t k = 0; k < indices_.size(); ++k)
    {
        v.row(k) = candidateValues.row(indices_[k]);
    }
    Values alpha;
    Eigen::MatrixX3d beta;
    solver_.solve(v, alpha, beta);
    evaluator_.assign(solver_.centres(), alpha, beta);
}

} // namespace dcprbf
