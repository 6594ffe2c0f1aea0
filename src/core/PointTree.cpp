#include "PointTree.hpp"

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

} // namespace dcprbf
