// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: basic types shared by every core class.
// OpenFOAM-free: only the standard library and Eigen.
#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <string>

namespace dcprbf
{

//- N points or N vectors, one row each (x y z), row-major so that an
//  OpenFOAM vectorField can be mapped without a copy.
using Points = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Values = Points;

//- Error raised for ill-posed input (duplicate points, sets that cannot carry
//  the polynomial, unknown names, ...). The message says what and where.
class Error : public std::runtime_error
{
public:
    explicit Error(const std::string& what) : std::runtime_error(what) {}
};

} // namespace dcprbf
