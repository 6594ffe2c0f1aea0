// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the distinct rows of a point set (bit-identical rows
// counted once), so that an interpolant is evaluated once per distinct
// point. In 2D the front and back points of the mesh map to the same plane
// coordinates: half the evaluations.
#pragma once

#include "Types.hpp"

#include <vector>

namespace dcprbf
{

class DistinctRows
{
public:
    //- The distinct rows of p, in the order of their first occurrence
    explicit DistinctRows(const Points& p);

    //- The distinct rows
    const Points& points() const { return points_; }

    //- The row of points() equal to row i of p
    Eigen::Index of(Eigen::Index i) const { return rowOf_[std::size_t(i)]; }

    //- Number of rows of p
    std::size_t size() const { return rowOf_.size(); }

private:
    Points points_;
    std::vector<Eigen::Index> rowOf_;
};

} // namespace dcprbf
