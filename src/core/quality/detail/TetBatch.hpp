// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the measures of many tetrahedra at once, laid out
// for SIMD (CellQualityScan's inner loop).
//
// A tetrahedron is given by its edge columns from one vertex, reference
// (e0, ea, eb) and current (f0, fa, fb): E0 = (e0 ea eb), E = (f0 fa fb),
// A = E E0^-1. measure() computes for every tetrahedron J = det A and
// |A|_F^2 as TetMeasures::measures does (E0^-1 det0 by cross products;
// a degenerate reference, det0^2 <= 1e-28 max|e|^6, gives J = a2 = -1), and
// TetMeasures::rankKey where J and a2 are in a range where the key neither
// overflows nor traps (else key 0: the caller ranks by the quality itself).
// The loop has no branch and no division by zero or overflow in any lane
// (OpenFOAM traps floating-point exceptions), so it vectorizes; on x86-64
// with GCC it is compiled for AVX2 and AVX-512 as well and the widest the
// processor has is picked at run time. No
// floating-point contraction: each tetrahedron's values are the same in
// the vector body, its remainder and every build (bit-identical results
// whatever the batch or thread count).
#pragma once

#include "LaneArrays.hpp"
#include "TetQuality.hpp"

#include <cstddef>
#include <vector>

namespace dcprbf
{
namespace detail
{

class TetBatch
{
public:
    //- Room for n tetrahedra (their values undefined until set)
    void resize(const std::size_t n) { lanes_.resize(n); }

    //- Number of tetrahedra
    std::size_t size() const { return lanes_.size(); }

    //- Tetrahedron t: reference and current edge columns (x y z each)
    inline void set
    (
        const std::size_t t,
        const double* e0, const double* ea, const double* eb,
        const double* f0, const double* fa, const double* fb
    )
    {
        const double* cols[6] = {e0, ea, eb, f0, fa, fb};
        for (int k = 0; k < 6; ++k)
        {
            for (int d = 0; d < 3; ++d)
            {
                lanes_.in(3*k + d, t) = cols[k][d];
            }
        }
    }

    //- Is there an AVX2 or AVX-512 build of the SIMD kernels on this
    //  processor, within the cap (else wide and narrow are the same build)?
    static bool wideAvailable();

    //- The vector width in bits the wide kernels run at (512, 256 or 0)
    static unsigned width();

    //- Cap the wide kernels' width at bits (>= 512: no cap; 256-511: AVX2
    //  where the processor has AVX-512; < 256: the default build);
    //  process-wide, for tests and benchmarks, not while kernels run
    static void limitWidth(unsigned bits);

    //- The cap (limitWidth's last argument; at first the environment's
    //  DCPRBF_SIMD_WIDTH, else 512)
    static unsigned widthCap();

    //- The cap a DCPRBF_SIMD_WIDTH value asks for (null: unset)
    static unsigned widthCapOf(const char* value);

    //- J, |A|_F^2 and the rank key of every tetrahedron
    //  (wide false: the default-target build even with AVX2 or AVX-512;
    //  the values are the same)
    void measure(TetQuality::Metric metric, bool wide = true);

    //- q[i] = TetMeasures::quality(J[i], a2[i], metric) (to ~1e-15) for
    //  ranked tetrahedra (J in (1e-30, 1e30), 0 < a2 < 1e25; TetKernel's
    //  cube root), i < n, in SIMD lanes
    static void qualities
    (
        std::size_t n,
        const double* J,
        const double* a2,
        double* q,
        TetQuality::Metric metric,
        bool wide = true
    );

    double J(const std::size_t t) const { return lanes_.out(0, t); }
    double a2(const std::size_t t) const { return lanes_.out(1, t); }
    double key(const std::size_t t) const { return lanes_.out(2, t); }

private:
    //- In: 18 components (e0 ea eb f0 fa fb, x y z each); out: J, a2, key
    LaneArrays lanes_{18, 3};
};

} // namespace detail
} // namespace dcprbf
