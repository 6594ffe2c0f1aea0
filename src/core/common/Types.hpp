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

//- An error relative to the largest displacement of d (the rows' norms): 0
//  where nothing moves by more than round-off of the length scale (1e-12 of
//  it: a motion passing through rest, sin(pi) = 1.2e-16, is not measured
//  against its own round-off)
inline double relativeToLargest(const double error, const Values& d, const double length)
{
    const double dMax = d.rows() ? d.rowwise().norm().maxCoeff() : 0;
    return dMax > 1e-12*length ? error/dMax : 0;
}

//- Error raised for ill-posed input (duplicate points, sets that cannot carry
//  the polynomial, unknown names, ...). The message says what and where.
class Error : public std::runtime_error
{
public:
    explicit Error(const std::string& what) : std::runtime_error(what) {}
};

} // namespace dcprbf
