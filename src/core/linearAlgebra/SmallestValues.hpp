// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the k smallest of n values, without a copy of all.
//
// A strided sample of the values (every 64th) estimates a bound that about
// 1.5 k + 64 of them do not exceed; one pass keeps the values at or below it
// and nth_element picks the k smallest among those. When fewer than k pass
// the bound (a sample that misjudged it), the values are copied and
// selected whole: the result is the same multiset either way. For a trial
// window (a few % of the cells) that is one pass and a selection among a
// few % of the values, not a copy and a selection of all of them.
#pragma once

#include <cstddef>
#include <vector>

namespace dcprbf
{

//- The k smallest of values[0 .. n) (k > n: all of them), in no order
std::vector<double> smallestValues(const double* values, std::size_t n, std::size_t k);

} // namespace dcprbf
