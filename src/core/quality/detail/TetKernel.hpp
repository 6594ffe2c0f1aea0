// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the tetrahedron measures of TetMeasures written for
// SIMD loops (TetBatch, PrismBatch, PlanarMapBatch): no branch, only selects
// of computed values; the selected lanes' operands are always in range (no
// division by zero, no overflow), and dispatch() masks floating-point
// exceptions while a kernel runs, as the compiler may compute ahead of a
// select in a lane whose result is then discarded.
//
// Include only in the kernels' .cpp files: on x86-64 with GCC it switches
// off, for the rest of the file, -fmath-errno (errno is never read; but GCC
// 12 keeps errno for std::sqrt inlined from <cmath> under the pragma: the
// sizeShape kernels vectorize only when the file is compiled with
// -fno-math-errno, as src/Make/options and dcprbfCore.cmake do; a warning
// below says when not), contraction (-ffp-contract=off: no FMA on any target, so
// every build gives the same bits) and -ftrapping-math (GCC vectorizes a
// select of floating-point values only when told that the operations do
// not trap: dispatch() masks the exceptions meanwhile). No other effect: no
// reassociation, IEEE results, the same in a vector body, its remainder and
// either build.
//
// dispatch<Kernel> runs Kernel::run<M> (M: the metric as a template
// argument) compiled for AVX-512 (512-bit vectors: 8 lanes) or AVX2 where
// the processor has them (GCC on x86-64; target attributes, not
// target_clones, which GCC 12 fails to compile on these loops), else for
// the default target.
#pragma once

#include "TetQuality.hpp"

#include <atomic>
#include <cfenv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#if defined(__FAST_MATH__)
    #error "dcpRBF: the quality kernels need IEEE arithmetic (no -ffast-math / -Ofast): their builds must give the same bits"
#endif

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
    #include <xmmintrin.h>
    #pragma GCC optimize("no-trapping-math", "no-math-errno", "fp-contract=off", "no-associative-math", "no-reciprocal-math")
    #define DCPRBF_X86_DISPATCH 1
    #ifndef __NO_MATH_ERRNO__
        #pragma GCC warning "dcpRBF: compile with -fno-math-errno: else the sizeShape quality kernels are scalar"
    #endif
#else
    #define DCPRBF_X86_DISPATCH 0
#endif
#if defined(__GNUC__)
    #define DCPRBF_ALWAYS_INLINE inline __attribute__((always_inline))
#else
    #define DCPRBF_ALWAYS_INLINE inline
#endif

namespace dcprbf
{
namespace detail
{
namespace tetKernel
{

//- The metric as a template argument (one loop per metric)
constexpr int sizeShape = int(TetQuality::Metric::sizeShape);
constexpr int size = int(TetQuality::Metric::size);
constexpr int shape = int(TetQuality::Metric::shape);

//- J and |A|_F^2 of the tetrahedron with reference edge columns e0 ea eb and
//  current f0 fa fb (A = E E0^-1); a degenerate reference (det0^2 <= 1e-28
//  max|e|^6) gives J = a2 = -1 (TetMeasures::measures)
DCPRBF_ALWAYS_INLINE void measures
(
    const double e0x, const double e0y, const double e0z,
    const double eax, const double eay, const double eaz,
    const double ebx, const double eby, const double ebz,
    const double f0x, const double f0y, const double f0z,
    const double fax, const double fay, const double faz,
    const double fbx, const double fby, const double fbz,
    double& J,
    double& a2
)
{
    // E0^-1 det0 = rows (ea x eb, eb x e0, e0 x ea)
    const double p0 = eay*ebz - eaz*eby, p1 = eaz*ebx - eax*ebz, p2 = eax*eby - eay*ebx;
    const double q0 = eby*e0z - ebz*e0y, q1 = ebz*e0x - ebx*e0z, q2 = ebx*e0y - eby*e0x;
    const double r0 = e0y*eaz - e0z*eay, r1 = e0z*eax - e0x*eaz, r2 = e0x*eay - e0y*eax;
    const double det0 = e0x*p0 + e0y*p1 + e0z*p2;
    const double l0 = e0x*e0x + e0y*e0y + e0z*e0z;
    const double la = eax*eax + eay*eay + eaz*eaz;
    const double lb = ebx*ebx + eby*eby + ebz*ebz;
    const double l0a = l0 > la ? l0 : la;
    const double s2 = l0a > lb ? l0a : lb;
    const bool valid = det0*det0 > 1e-28*s2*s2*s2;
    const double d = valid ? det0 : 1.0;

    // det E = f0 . (fa x fb)
    const double detE =
        f0x*(fay*fbz - faz*fby) + f0y*(faz*fbx - fax*fbz) + f0z*(fax*fby - fay*fbx);

    // |E adj|_F^2: (E adj)_rc = f0_r p_c + fa_r q_c + fb_r r_c
    const double m00 = f0x*p0 + fax*q0 + fbx*r0;
    const double m01 = f0x*p1 + fax*q1 + fbx*r1;
    const double m02 = f0x*p2 + fax*q2 + fbx*r2;
    const double m10 = f0y*p0 + fay*q0 + fby*r0;
    const double m11 = f0y*p1 + fay*q1 + fby*r1;
    const double m12 = f0y*p2 + fay*q2 + fby*r2;
    const double m20 = f0z*p0 + faz*q0 + fbz*r0;
    const double m21 = f0z*p1 + faz*q1 + fbz*r1;
    const double m22 = f0z*p2 + faz*q2 + fbz*r2;
    const double sum =
        m00*m00 + m01*m01 + m02*m02
      + m10*m10 + m11*m11 + m12*m12
      + m20*m20 + m21*m21 + m22*m22;

    const double Jd = detE/d, a2d = sum/(d*d);
    J = valid ? Jd : -1.0;
    a2 = valid ? a2d : -1.0;
}


//- TetMeasures::rankKey for metric M where J is in (1e-30, 1e30) and
//  a2 in (1e-40, 1e25), 0 elsewhere (rank by the quality; TetMeasures::
//  keyRange).
template<int M>
DCPRBF_ALWAYS_INLINE double key(const double J, const double a2)
{
    // computed from J and a2 as they are; kept only in the range (a2 >=
    // 3 J^(2/3) > 3e-20 for J > 1e-30: the bound 1e-40 excludes round-off
    // alone), where nothing overflows or divides by zero (elsewhere a
    // discarded lane may: dispatch() masks the exceptions)
    double k;
    if (M == size)
    {
        const double r = 1.0/J;
        k = J < r ? J : r;
    }
    else if (M == shape)
    {
        k = 27.0*J*J/(a2*a2*a2);
    }
    else
    {
        const double a6 = a2*a2*a2;
        const double J4 = (J*J)*(J*J);
        const double J7 = J4*(J*J*J);
        k = 729.0*(J < 1 ? J7 : J)/(a6*a6);
    }
    k = J > 1e-30 ? k : 0.0;
    k = J < 1e30 ? k : 0.0;
    k = a2 > 1e-40 ? k : 0.0;
    return a2 < 1e25 ? k : 0.0;
}

//- The cube root of x in [1e-30, 1e30] to ~1 ulp (std::cbrt is a scalar
//  libm call): a first guess from the float's bits (exponent / 3, within a
//  few %), then three Halley steps y (y^3 + 2x)/(2 y^3 + x) (cubic
//  convergence)
DCPRBF_ALWAYS_INLINE double cubeRoot(const double x)
{
    const float xf = float(x);
    std::uint32_t i;
    std::memcpy(&i, &xf, sizeof(i));
    i = i/3u + 709921077u;
    float yf;
    std::memcpy(&yf, &i, sizeof(yf));
    double y = yf;
    for (int k = 0; k < 3; ++k)
    {
        const double y3 = y*y*y;
        y = y*(y3 + 2*x)/(2*y3 + x);
    }
    return y;
}


//- TetMeasures::quality for metric M where J is in [1e-30, 1e30] and
//  a2 > 0 (a ranked tetrahedron), with cubeRoot: the same to ~1e-15
template<int M>
DCPRBF_ALWAYS_INLINE double quality(const double J, const double a2)
{
    const double r = 1.0/J;
    const double fSize = J < r ? J : r;
    const double c = cubeRoot(J);
    const double fShape = 3.0*(c*c)/a2;
    if (M == size) return fSize;
    if (M == shape) return fShape;
    return std::sqrt(fSize)*fShape;
}


//- A kernel for dispatch over items in SIMD lanes: Lane::item<M>(t, s,
//  in, out) for every item t < n (components s apart)
template<class Lane>
struct Lanes
{
    template<int M>
    static DCPRBF_ALWAYS_INLINE void run
    (
        const std::size_t n,
        const std::size_t s,
        const double* __restrict in,
        double* __restrict out
    )
    {
        #pragma omp simd
        for (std::size_t t = 0; t < n; ++t)
        {
            Lane::template item<M>(t, s, in, out);
        }
    }
};


//- Kernel::run<M>(args) for the metric
template<class Kernel, class... Args>
DCPRBF_ALWAYS_INLINE void byMetric(const TetQuality::Metric metric, Args... args)
{
    switch (metric)
    {
        case TetQuality::Metric::size: Kernel::template run<size>(args...); break;
        case TetQuality::Metric::shape: Kernel::template run<shape>(args...); break;
        default: Kernel::template run<sizeShape>(args...); break;
    }
}

#if DCPRBF_X86_DISPATCH
//- byMetric compiled for AVX2 (256-bit vectors; no FMA: fp-contract=off)
template<class Kernel, class... Args>
__attribute__((target("avx2"))) void byMetricAvx2
(
    const TetQuality::Metric metric,
    Args... args
)
{
    byMetric<Kernel>(metric, args...);
}

//- byMetric compiled for AVX-512 (512-bit vectors; the target enables FMA,
//  which fp-contract=off above keeps out: the same bits as the others)
template<class Kernel, class... Args>
__attribute__((target("avx512f,avx512dq,avx512vl,prefer-vector-width=512"))) void byMetricAvx512
(
    const TetQuality::Metric metric,
    Args... args
)
{
    byMetric<Kernel>(metric, args...);
}
#endif

template<class Kernel, class... Args>
void byMetricDefault(const TetQuality::Metric metric, Args... args)
{
    byMetric<Kernel>(metric, args...);
}

//- The widest vectors the processor offers the kernels, in bits: 512
//  (AVX-512 F, DQ and VL), 256 (AVX2) or 0 (none: the default target's
//  build; also where this compiler cannot build the others)
inline unsigned processorWidth()
{
    #if DCPRBF_X86_DISPATCH
    static const unsigned w = []
    {
        __builtin_cpu_init();
        if
        (
            __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq")
         && __builtin_cpu_supports("avx512vl")
        )
        {
            return 512u;
        }
        return __builtin_cpu_supports("avx2") ? 256u : 0u;
    }();
    return w;
    #else
    return 0;
    #endif
}

//- The cap a DCPRBF_SIMD_WIDTH value asks for: its number of bits (at
//  most 512); 512 when unset (null) or not a whole number
inline unsigned widthCapOf(const char* value)
{
    char* end = nullptr;
    const unsigned long w = value ? std::strtoul(value, &end, 10) : 512;
    if (value && (end == value || *end != '\0' || *value == '-'))
    {
        return 512;
    }
    return unsigned(w < 512 ? w : 512);
}

//- The cap on the width the kernels use, in bits: at first the
//  environment's DCPRBF_SIMD_WIDTH (e.g. 256: AVX2 on a processor whose
//  clock drops under 512-bit code), else 512; process-wide, tests and
//  benchmarks lower it to run the narrower builds (not while kernels run)
inline std::atomic<unsigned>& widthLimit()
{
    static std::atomic<unsigned> limit{widthCapOf(std::getenv("DCPRBF_SIMD_WIDTH"))};
    return limit;
}

//- The width the wide kernels run at: the widest build (512, 256 or 0)
//  within both the processor's width and the cap
inline unsigned widest()
{
    const unsigned p = processorWidth();
    const unsigned c = widthLimit().load(std::memory_order_relaxed);
    return c >= 512 ? p : c >= 256 ? (p < 256 ? p : 256u) : 0u;
}

//- Kernel::run<metric>(args): if wide, the AVX-512 or AVX2 build as
//  widest() says, else the default one (the same values: no contraction)
template<class Kernel, class... Args>
void dispatch(const TetQuality::Metric metric, const bool wide, Args... args)
{
    #if DCPRBF_X86_DISPATCH
    // With -fno-trapping-math GCC may move an operation ahead of a select
    // (x*x of both arms, then the select): a lane whose result is
    // discarded may then overflow. So every floating-point exception is
    // masked while a kernel runs (OpenFOAM traps some) and the caller's
    // masks and flags are restored after it (MXCSR: SSE/AVX only; the
    // kernels use no x87)
    const unsigned csr = _mm_getcsr();
    _mm_setcsr(csr | 0x1F80u);
    const unsigned width = wide ? widest() : 0;
    if (width >= 512)
    {
        byMetricAvx512<Kernel>(metric, args...);
    }
    else if (width >= 256)
    {
        byMetricAvx2<Kernel>(metric, args...);
    }
    else
    {
        byMetricDefault<Kernel>(metric, args...);
    }
    _mm_setcsr(csr);
    #else
    // the same, portably (the operations are computed in every lane here
    // too, as written)
    (void)wide;
    std::fenv_t env;
    std::feholdexcept(&env);
    byMetricDefault<Kernel>(metric, args...);
    std::fesetenv(&env);
    #endif
}

} // namespace tetKernel
} // namespace detail
} // namespace dcprbf
