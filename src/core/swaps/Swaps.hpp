// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core, module swaps: the error-guided trial swaps on a
// dynamic control set without a mesh: a change tried and kept or given up
// (SetTransaction), one step's trials (TrialSwaps), when they are made
// (TrialSchedule), and the kept swaps phased in (SwapBlend, a SetBlend).
#pragma once

#include "SetBlend.hpp"
#include "SetTransaction.hpp"
#include "TrialSwaps.hpp"
#include "TrialSchedule.hpp"
#include "SwapBlend.hpp"
