// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Benchmark helpers: wall-clock timing, peak memory, table output.
#pragma once

#include <sys/resource.h>

#include <algorithm>
#include <cstdlib>
#include <chrono>
#include <cstdio>
#include <string>

namespace dcprbf
{
namespace bench
{

//- Wall-clock seconds of one call of f
template<class F>
double seconds(F&& f)
{
    const auto t0 = std::chrono::steady_clock::now();
    f();
    const auto t1 = std::chrono::steady_clock::now();
    return std::chrono::duration<double>(t1 - t0).count();
}

//- Smallest of `repeats` timings (robust against other load)
template<class F>
double minSeconds(int repeats, F&& f)
{
    double best = 1e300;
    for (int r = 0; r < repeats; ++r) best = std::min(best, seconds(f));
    return best;
}

//- Keep the compiler from dropping the writes to what p points to
inline void keepWrites(const void* p)
{
    asm volatile("" : : "g"(p) : "memory");
}

//- Peak resident set size of this process so far, MB
inline double peakRssMB()
{
    rusage u;
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss/1024.0;  // kB on Linux
}

//- 1-minute load average (other processes compete for the cores)
inline double loadAverage()
{
    double l[1] = {0};
    return getloadavg(l, 1) == 1 ? l[0] : -1;
}

//- printf to a std::string
template<class... A>
std::string fmt(const char* f, A... a)
{
    char buf[256];
    std::snprintf(buf, sizeof buf, f, a...);
    return buf;
}

} // namespace bench
} // namespace dcprbf
