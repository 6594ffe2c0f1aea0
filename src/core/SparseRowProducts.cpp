// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "SparseRowProducts.hpp"

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
    #include <immintrin.h>
    // no contraction into FMA in the AVX2 build: the scalar loop's bits
    #pragma GCC optimize("fp-contract=off")
    #define DCPRBF_SPARSE_X86 1
#else
    #define DCPRBF_SPARSE_X86 0
#endif

namespace dcprbf
{

namespace
{

template<int C, class Index>
void scalarRows
(
    const std::size_t i0, const std::size_t i1, const std::size_t* outer,
    const Index* inner, const double* values, const double* a, double* out
)
{
    constexpr int S = sparseRowStride(C), U = 4;
    for (std::size_t i = i0; i < i1; ++i)
    {
        std::size_t k = outer[i];
        const std::size_t end = outer[i + 1];
        double v[U][C] = {};
        for (; k + U - 1 < end; k += U)
        {
            for (int u = 0; u < U; ++u)
            {
                const double* au = a + S*std::size_t(inner[k + u]);
                for (int q = 0; q < C; ++q) v[u][q] += values[k + u]*au[q];
            }
        }
        for (; k < end; ++k)
        {
            const double* a0 = a + S*std::size_t(inner[k]);
            for (int q = 0; q < C; ++q) v[0][q] += values[k]*a0[q];
        }
        double* o = out + C*(i - i0);
        for (int q = 0; q < C; ++q) o[q] = (v[0][q] + v[1][q]) + (v[2][q] + v[3][q]);
    }
}

#if DCPRBF_SPARSE_X86
//- Three columns: AVX2, a's rows four apart
template<class Index>
__attribute__((target("avx2"))) void avx2Rows
(
    const std::size_t i0, const std::size_t i1, const std::size_t* outer,
    const Index* inner, const double* values, const double* a, double* out
)
{
    for (std::size_t i = i0; i < i1; ++i)
    {
        std::size_t k = outer[i];
        const std::size_t end = outer[i + 1];
        __m256d v0 = _mm256_setzero_pd(), v1 = v0, v2 = v0, v3 = v0;
        const auto term = [&](const std::size_t e)
        {
            return _mm256_mul_pd
            (
                _mm256_set1_pd(values[e]), _mm256_loadu_pd(a + 4*std::size_t(inner[e]))
            );
        };
        for (; k + 3 < end; k += 4)
        {
            v0 = _mm256_add_pd(v0, term(k));
            v1 = _mm256_add_pd(v1, term(k + 1));
            v2 = _mm256_add_pd(v2, term(k + 2));
            v3 = _mm256_add_pd(v3, term(k + 3));
        }
        for (; k < end; ++k)
        {
            v0 = _mm256_add_pd(v0, term(k));
        }
        alignas(32) double r[4];
        _mm256_store_pd(r, _mm256_add_pd(_mm256_add_pd(v0, v1), _mm256_add_pd(v2, v3)));
        double* o = out + 3*(i - i0);
        o[0] = r[0];
        o[1] = r[1];
        o[2] = r[2];
    }
}
#endif

} // namespace


bool sparseRowProductsAvx2()
{
    #if DCPRBF_SPARSE_X86
    static const bool avx2 = []
    {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") != 0;
    }();
    return avx2;
    #else
    return false;
    #endif
}


template<class Index>
void sparseRowProducts
(
    const int C,
    const std::size_t i0,
    const std::size_t i1,
    const std::size_t* outer,
    const Index* inner,
    const double* values,
    const double* a,
    double* v,
    const bool wide
)
{
    #if DCPRBF_SPARSE_X86
    if (wide && C == 3 && sparseRowProductsAvx2())
    {
        avx2Rows(i0, i1, outer, inner, values, a, v);
        return;
    }
    #else
    (void)wide;
    #endif
    if (C == 2)
    {
        scalarRows<2>(i0, i1, outer, inner, values, a, v);
    }
    else
    {
        scalarRows<3>(i0, i1, outer, inner, values, a, v);
    }
}


template void sparseRowProducts<std::uint8_t>
(
    int, std::size_t, std::size_t, const std::size_t*, const std::uint8_t*,
    const double*, const double*, double*, bool
);
template void sparseRowProducts<std::uint16_t>
(
    int, std::size_t, std::size_t, const std::size_t*, const std::uint16_t*,
    const double*, const double*, double*, bool
);
template void sparseRowProducts<int>
(
    int, std::size_t, std::size_t, const std::size_t*, const int*,
    const double*, const double*, double*, bool
);

} // namespace dcprbf
