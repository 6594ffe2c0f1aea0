// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core, module selection: choosing the control set: greedy
// data reduction (GreedySelector over a GreedyModel; IncrementalGreedyModel
// updates every candidate's error in O(Nb N) per point) and the dynamic
// control set (DynamicControlSet: swaps by either rule, the old and new
// interpolants blended, restart state).
#pragma once

#include "GreedyModel.hpp"
#include "IncrementalGreedyModel.hpp"
#include "GreedySelector.hpp"
#include "DynamicControlSet.hpp"
