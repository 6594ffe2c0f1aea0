/*---------------------------------------------------------------------------*\
  dcpRBF benchmarks
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    The tests' cell-by-cell quality (tests/openfoam/common/cellByCellQuality),
    the reference the benchmark times the flat scans against, compiled here
    (its object in this benchmark's build folder).

\*---------------------------------------------------------------------------*/

#include "cellByCellQuality.C"

// ************************************************************************* //
