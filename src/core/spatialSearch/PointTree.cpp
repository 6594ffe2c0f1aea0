// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "PointTree.hpp"

#include <algorithm>

namespace dcprbf
{

PointTree::PointTree(const Points& points)
:
    adaptor_{points},
    tree_(new Tree(3, adaptor_, nanoflann::KDTreeSingleIndexAdaptorParams(16)))
{
    tree_->buildIndex();
}


std::size_t PointTree::nearest(const double* q, double& distSq) const
{
    if (size() == 0)
    {
        throw Error("nearest-point query on an empty point set");
    }
    std::uint32_t index = 0;
    nanoflann::KNNResultSet<double, std::uint32_t> result(1);
    result.init(&index, &distSq);
    tree_->findNeighbors(result, q, searchParams());
    return index;
}


bool PointTree::findCoincident
(
    const Points& points,
    double tol,
    Eigen::Index& i,
    Eigen::Index& j
)
{
    const PointTree tree(points);
    for (Eigen::Index a = 0; a < points.rows(); ++a)
    {
        Eigen::Index other = -1;
        tree.forEachWithin(points.row(a).data(), tol, [&](std::size_t b, double)
        {
            if (Eigen::Index(b) != a && (other < 0 || Eigen::Index(b) < other))
            {
                other = b;
            }
        });
        if (other >= 0)
        {
            i = std::min(a, other);
            j = std::max(a, other);
            return true;
        }
    }
    return false;
}

} // namespace dcprbf
