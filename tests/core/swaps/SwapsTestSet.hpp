// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// The control set shared by the swaps module's tests: 200 candidates in the
// unit cube, every fourth a control point, solved for a smooth field.
#pragma once

#include "DynamicControlSet.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace dcprbf
{
namespace test
{

struct SwapsTestSet : ::testing::Test
{
    Points cand = randomPoints(200, 3, 31);
    Values v = smoothField(cand);
    RadialKernel k = RadialKernel::fromName("WendlandC2", 0.6);
    DynamicControlSet set
    {
        cand, std::vector<char>(cand.rows(), 1), k, true, 3, DynamicControlSet::Options()
    };

    void SetUp() override
    {
        std::vector<Eigen::Index> idx;
        for (Eigen::Index i = 0; i < cand.rows(); i += 4) idx.push_back(i);
        set.reset(idx);
        set.solve(v);
    }

    //- The coefficients (alpha, beta) of state's interpolant of v
    std::pair<Values, Eigen::MatrixX3d> coefficients(const DynamicControlSet::State& s) const
    {
        Values vc(s.indices.size(), 3);
        for (std::size_t j = 0; j < s.indices.size(); ++j) vc.row(j) = v.row(s.indices[j]);
        Values alpha;
        Eigen::MatrixX3d beta;
        s.solver.solve(vc, alpha, beta);
        return {alpha, beta};
    }
};

} // namespace test
} // namespace dcprbf
