/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFThreads.H"
#include "ThreadCount.hpp"
#include "Pstream.H"
#include "dcpRBFVersion.H"
#include "OSspecific.H"

#include <sched.h>

#ifdef _OPENMP
    #include <omp.h>
#endif

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFThreads::coresAvailable()
{
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) == 0)
    {
        return CPU_COUNT(&set);
    }
    #ifdef _OPENMP
    return omp_get_num_procs();
    #else
    return 1;
    #endif
}


Foam::label Foam::dcpRBFThreads::ranksOnNode()
{
    if (!Pstream::parRun())
    {
        return 1;
    }
    List<string> hosts(Pstream::nProcs());
    hosts[Pstream::myProcNo()] = hostName();
    dcpRBFCompat::allGatherList(hosts);
    label n = 0;
    for (const string& h : hosts)
    {
        n += (h == hosts[Pstream::myProcNo()]);
    }
    return n;
}


Foam::label Foam::dcpRBFThreads::set
(
    const label nPoints,
    const label pointsPerThread
)
{
    #ifdef _OPENMP
    // collective: every rank takes part, whatever its environment
    const label ranks = ranksOnNode();
    if (getEnv("OMP_NUM_THREADS").empty())
    {
        omp_set_num_threads
        (
            dcprbf::threadsForSize
            (
                dcprbf::threadsPerRank(coresAvailable(), ranks),
                nPoints,
                pointsPerThread
            )
        );
    }
    return omp_get_max_threads();
    #else
    return 1;
    #endif
}


// ************************************************************************* //
