/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFResidentMemory.H"

#include <fstream>
#include <sstream>
#include <string>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::dcpRBFResidentMemory::statusMB(const char* key)
{
    std::ifstream status("/proc/self/status");
    std::string line;
    const std::string k(key);
    while (std::getline(status, line))
    {
        if (line.compare(0, k.size(), k) == 0)
        {
            std::istringstream is(line.substr(k.size()));
            double kB = -1;
            is >> kB;
            return is ? kB/1024.0 : -1;
        }
    }
    return -1;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFResidentMemory::dcpRBFResidentMemory()
:
    startMB_(-1)
{
    std::ofstream reset("/proc/self/clear_refs");
    reset << "5" << std::flush;
    if (reset)
    {
        startMB_ = statusMB("VmRSS:");
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dcpRBFResidentMemory::peakAboveStartMB() const
{
    const scalar peak = statusMB("VmHWM:");
    return startMB_ < 0 || peak < 0 ? -1 : peak - startMB_;
}


// ************************************************************************* //
