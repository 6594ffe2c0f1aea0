// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// The kernel x polynomial x dimension parameters shared by the core's
// parameterised tests: every kernel, with and without the polynomial (TPS
// only with it), in 2D and 3D.
#pragma once

#include "RadialKernel.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <tuple>
#include <vector>

namespace dcprbf
{
namespace test
{

//- kernel name, polynomial, dimension
using KernelCase = std::tuple<std::string, bool, int>;

inline std::vector<KernelCase> kernelCases()
{
    std::vector<KernelCase> cases;
    for (const auto& name : RadialKernel::names())
    {
        for (bool poly : {false, true})
        {
            if (name == "TPS" && !poly) continue;
            for (int dim : {2, 3}) cases.emplace_back(name, poly, dim);
        }
    }
    return cases;
}

//- The cases for which keep(case) holds, for tests that apply to only some
//  of them (instantiate those over this list instead of returning early)
inline std::vector<KernelCase> kernelCases
(
    const std::function<bool(const KernelCase&)>& keep
)
{
    std::vector<KernelCase> cases;
    for (const KernelCase& c : kernelCases())
    {
        if (keep(c)) cases.push_back(c);
    }
    return cases;
}

//- Test names such as WendlandC2_poly_3D
inline std::string kernelCaseName(const ::testing::TestParamInfo<KernelCase>& info)
{
    return std::get<0>(info.param)
        + (std::get<1>(info.param) ? "_poly" : "_noPoly")
        + "_" + std::to_string(std::get<2>(info.param)) + "D";
}

} // namespace test
} // namespace dcprbf
