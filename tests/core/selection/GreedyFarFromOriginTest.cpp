// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit test of GreedySelector on candidates far from the origin (terrain in
// UTM coordinates: 6.6e5, 4.75e6): the seed is checked in the candidates'
// frame, so a translated set gives the same selection as the original one.
#include "GreedySelector.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

using namespace dcprbf;

namespace
{

TEST(GreedyFarFromOrigin, TranslatedSetSelectsTheSamePoints)
{
    for (const int dim : {2, 3})
    {
        // two parallel planes 1000 apart (a flat moving ground, a flat top)
        const Points u = test::randomPoints(200, dim, 7);
        Points x(u.rows(), 3);
        x.setZero();
        for (Eigen::Index i = 0; i < u.rows(); ++i)
        {
            x(i, 0) = 1000*u(i, 0);
            x(i, 1) = dim == 3 ? 1000*u(i, 1) : (i % 2)*1000.0;
            if (dim == 3) x(i, 2) = (i % 2)*1000.0;
        }
        Values d = Values::Zero(x.rows(), 3);
        for (Eigen::Index i = 0; i < x.rows(); i += 2)
        {
            d(i, dim - 1) = 50*std::sin(x(i, 0)/300.0);   // the ground moves
        }
        Points far = x;
        far.col(0).array() += 6.6e5;
        far.col(1).array() += 4.75e6;

        GreedyOptions o;
        o.tolerance = 1e-2;
        const GreedySelector g(RadialKernel::fromName("WendlandC2", 1500.0), true, dim, o);
        const GreedyResult near = g.select(x, d);
        std::vector<Eigen::Index> shifted;
        ASSERT_NO_THROW(shifted = g.select(far, d).selected) << dim << "D";
        EXPECT_EQ(near.selected, shifted) << dim << "D";
    }
}

} // namespace
