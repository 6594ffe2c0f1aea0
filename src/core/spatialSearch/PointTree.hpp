// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: kd-tree over a fixed set of 3D points (nanoflann).
//
// The dataset adaptor follows nanoflann's adaptor style (kdtree_get_point_count,
// kdtree_get_pt, kdtree_get_bbox). Radius queries take a callback that receives
// each neighbour as it is found, so evaluation loops accumulate kernel sums
// without building a result list.
#pragma once

#include "Types.hpp"

#include <nanoflann.hpp>

#include <cstdint>
#include <memory>

namespace dcprbf
{

class PointTree
{
public:
    //- Build over a copy of the points
    explicit PointTree(const Points& points);

    PointTree(const PointTree&) = delete;
    PointTree& operator=(const PointTree&) = delete;

    std::size_t size() const { return adaptor_.points.rows(); }

    //- Index of the nearest point to q (the tree must not be empty), and
    //  its squared distance in distSq
    std::size_t nearest(const double* q, double& distSq) const;

    //- First pair i < j of points closer than tol (i over rows in order),
    //  or false when all points are at least tol apart
    static bool findCoincident
    (
        const Points& points,
        double tol,
        Eigen::Index& i,
        Eigen::Index& j
    );

    //- Is a point closer than radius to q? (the search stops at the first)
    bool anyWithin(const double* q, const double radius) const
    {
        AnyResult result{radius*radius};
        tree_->findNeighbors(result, q, searchParams());
        return result.found;
    }

    //- Call f(index, distSq) for every point with |p - q| < radius
    template<class F>
    void forEachWithin(const double* q, double radius, F&& f) const
    {
        CallbackResult<F> result{radius*radius, f};
        tree_->findNeighbors(result, q, searchParams());
    }

private:
    //- nanoflann dataset adaptor over a row-major N x 3 matrix
    struct Adaptor
    {
        Points points;
        std::size_t kdtree_get_point_count() const { return points.rows(); }
        double kdtree_get_pt(std::size_t i, std::size_t d) const
        {
            return points(i, d);
        }
        template<class BBox> bool kdtree_get_bbox(BBox&) const { return false; }
    };

    //- nanoflann result set that forwards every hit to a callback
    template<class F>
    struct CallbackResult
    {
        double radiusSq;
        F& f;
        bool full() const { return true; }
        std::size_t size() const { return 0; }
        double worstDist() const { return radiusSq; }
        bool addPoint(double distSq, std::uint32_t i)
        {
            if (distSq < radiusSq) f(std::size_t(i), distSq);
            return true;
        }
    };

    //- nanoflann result set that stops the search at the first hit
    struct AnyResult
    {
        double radiusSq;
        bool found = false;
        bool full() const { return true; }
        std::size_t size() const { return 0; }
        double worstDist() const { return radiusSq; }
        bool addPoint(double distSq, std::uint32_t)
        {
            found = found || distSq < radiusSq;
            return !found;
        }
    };

    using Tree = nanoflann::KDTreeSingleIndexAdaptor
    <
        nanoflann::L2_Simple_Adaptor<double, Adaptor>, Adaptor, 3, std::uint32_t
    >;

#if NANOFLANN_VERSION < 0x150
    using SearchParams = nanoflann::SearchParams;
#else
    using SearchParams = nanoflann::SearchParameters;
#endif
    static SearchParams searchParams() { return SearchParams(); }

    Adaptor adaptor_;
    std::unique_ptr<Tree> tree_;
};

} // namespace dcprbf
