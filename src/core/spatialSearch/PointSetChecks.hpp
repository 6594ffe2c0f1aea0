// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: validation of control/candidate point sets, shared
// by IncrementalSaddleSolver, GreedySelector and the tests' reference
// RbfInterpolant so that the same input gives the same Error message
// everywhere.
//
// Two points coincide when closer than 1e-10 x the diagonal of the set's
// bounding box (round-off distance: their kernel rows would be identical).
#pragma once

#include "LinearPolynomial.hpp"

namespace dcprbf
{

class PointSetChecks
{
public:
    //- dim + 1 with the polynomial, 1 without
    static Eigen::Index minimumSize(const LinearPolynomial& polynomial);

    //- Diagonal of the bounding box of the rows of x (0 when empty)
    static double extent(const Points& x);

    //- Finite coordinates, z = 0 in 2D; `what` names the set in messages
    static void checkCoordinates(const Points& x, int dim, const char* what);

    //- No two rows coincide; the message names the first pair
    static void checkDistinct(const Points& x, const char* what);

    //- A complete control set: at least minimumSize() points, coordinates,
    //  distinct, carries the polynomial (collinear/coplanar message)
    static void checkControlSet(const Points& x, const LinearPolynomial& polynomial);
};

} // namespace dcprbf
