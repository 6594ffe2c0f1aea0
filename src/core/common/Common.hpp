// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core, module common: the core's Eigen types (Types.hpp)
// and the default number of threads per process (ThreadCount).
#pragma once

#include "Types.hpp"
#include "ThreadCount.hpp"
