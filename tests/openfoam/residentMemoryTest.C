/*---------------------------------------------------------------------------*\
  dcpRBF tests: dcpRBFResidentMemory measures a window's own peak
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFResidentMemory.H"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

using namespace Foam;

namespace
{

//- n megabytes allocated and touched (resident), then freed
void touchMB(const std::size_t n)
{
    const std::size_t bytes = n << 20;
    std::unique_ptr<char[]> block(new char[bytes]);
    std::memset(block.get(), 1, bytes);
    volatile char keep = block[bytes - 1];
    static_cast<void>(keep);
}

} // namespace


// The window's peak above its start is what was allocated in it: an
// earlier, larger peak of the process is reset when the window opens (not
// counted), and the start is the resident memory then (not zero)
TEST(ResidentMemory, WindowPeakIsItsOwnAllocation)
{
    EXPECT_GT(dcpRBFResidentMemory::residentMB(), 1);
    touchMB(400);
    const dcpRBFResidentMemory window;
    ASSERT_GT(window.startMB(), 1);
    touchMB(100);
    const scalar peak = window.peakAboveStartMB();
    EXPECT_GT(peak, 90);
    EXPECT_LT(peak, 150);
}


// ************************************************************************* //
