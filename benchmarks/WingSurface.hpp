// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Benchmark geometry: the surface of a tapered, swept wing with NACA 0012
// sections, its deformation, and volume points around it.
//
// Section (chord c, x from the leading edge):
//     z_t(x) = 0.6 c (0.2969 sqrt(x/c) - 0.1260 (x/c) - 0.3516 (x/c)^2
//                     + 0.2843 (x/c)^3 - 0.1015 (x/c)^4)
// (upper +z_t, lower -z_t, blunt trailing edge), chordwise cosine spacing.
// Planform: semi-span b along y, root chord c_r, chord c(y) = c_r (1 - (1 -
// taper) y/b), leading edge at x = y tan(sweep).
// Deformation: bending w(y) = bend b (y/b)^2 in z, and a twist theta(y) =
// twist y/b about the quarter-chord line (nose down).
#pragma once

#include "Types.hpp"

namespace dcprbf
{
namespace bench
{

struct Wing
{
    double rootChord = 1.0;
    double taper = 0.4;
    double semiSpan = 3.0;
    double sweepDeg = 30.0;
    double bend = 0.08;      // tip deflection / semi-span
    double twistDeg = 6.0;   // tip twist

    //- nSpan stations x nChord points around each section (upper and lower
    //  surface, leading edge once), all distinct
    Points surface(int nSpan, int nChord) const;

    //- Displacement of surface points (bending and twist)
    Values displacement(const Points& surface) const;

    //- n pseudo-random points in the box around the wing (volume mesh stand-in)
    Points volume(std::size_t n, unsigned seed) const;
};

} // namespace bench
} // namespace dcprbf
