// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core, module parallel: a problem divided over ranks
// without MPI in the core. Collective is the interface of the operations
// the core needs (the adapter implements it with Pstream), SerialCollective
// the single rank, CandidateRows candidate points in blocks over the ranks
// with the global choices a selection makes on them.
#pragma once

#include "Collective.hpp"
#include "SerialCollective.hpp"
#include "CandidateRows.hpp"
