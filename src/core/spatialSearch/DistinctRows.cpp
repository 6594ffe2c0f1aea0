// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "DistinctRows.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace dcprbf
{

DistinctRows::DistinctRows(const Points& p)
:
    rowOf_(std::size_t(p.rows()))
{
    if (!p.allFinite())
    {
        throw std::invalid_argument("DistinctRows: a point that is not finite");
    }

    // rows sorted lexicographically (ties by index): equal rows adjacent,
    // the first of each run its first occurrence
    std::vector<Eigen::Index> order(std::size_t(p.rows()));
    std::iota(order.begin(), order.end(), Eigen::Index(0));
    const auto less = [&p](Eigen::Index a, Eigen::Index b)
    {
        for (Eigen::Index d = 0; d < p.cols(); ++d)
        {
            if (p(a, d) != p(b, d)) return p(a, d) < p(b, d);
        }
        return a < b;
    };
    std::sort(order.begin(), order.end(), less);
    std::vector<Eigen::Index> first(std::size_t(p.rows()));
    for (std::size_t k = 0; k < order.size(); ++k)
    {
        const bool same = k > 0 && (p.row(order[k]).array() == p.row(order[k - 1]).array()).all();
        first[std::size_t(order[k])] = same ? first[std::size_t(order[k - 1])] : order[k];
    }

    // distinct rows numbered in order of first occurrence
    std::vector<Eigen::Index> number(std::size_t(p.rows()), -1);
    Eigen::Index n = 0;
    for (std::size_t i = 0; i < rowOf_.size(); ++i)
    {
        const std::size_t f = std::size_t(first[i]);
        if (number[f] < 0) number[f] = n++;
        rowOf_[i] = number[f];
    }
    points_.resize(n, p.cols());
    for (std::size_t i = 0; i < rowOf_.size(); ++i)
    {
        points_.row(rowOf_[i]) = p.row(Eigen::Index(i));
    }
}

} // namespace dcprbf
