// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: points in Morton (Z-curve) order, so that a loop in
// that order visits neighbouring points together. The cell-quality scans
// visit their cells so: a mesh whose cells are numbered without locality (a
// mesh generator's order, not renumbered) reads its points from memory
// nearly in order instead of at random.
#pragma once

#include <cstddef>
#include <vector>

namespace dcprbf
{

//- The indices 0 .. n-1 of the points x (x y z per point) sorted by their
//  Morton key on a 2^21 grid over their bounding box (ties by index)
std::vector<int> mortonOrder(const double* x, std::size_t n);

} // namespace dcprbf
