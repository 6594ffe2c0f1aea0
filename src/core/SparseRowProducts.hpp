// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the rows of a compressed sparse matrix times a
// dense matrix of 2 or 3 columns (StoredEvaluation's stored products).
//
// Row i's result, column q: the sum over its entries k of
// values[k] a[S inner[k] + q], in four interleaved partial sums (entry k of
// the row's unrolled part into sum k mod 4, the rest into the first; four
// independent addition chains: with two, the additions' latency bounded
// the product, 2 cycles per entry), then (s0 + s1) + (s2 + s3).
// a's rows are S apart: S = 2 for 2 columns, 4 for 3 (the fourth zero).
//
// With vectors (wide, 3 columns: AVX2 where the processor has it, GCC on
// x86-64) an entry's products and sums are the lanes of one vector: one
// load of a's row, not three, and no contraction: the same operations in
// the same order as the scalar loop, the same bits. (Two columns: the
// scalar loop, which GCC's code runs as fast as SSE2 vectors did.)
#pragma once

#include <cstddef>
#include <cstdint>

namespace dcprbf
{

//- The stride of a's rows for C columns (2 or 3)
constexpr int sparseRowStride(const int C) { return C == 3 ? 4 : 2; }

//- v[C (i - i0) + q] = row i times a, column q < C, for rows i0 .. i1 of
//  the rows outer (row i's entries outer[i] .. outer[i+1]), inner, values;
//  a: sparseRowStride(C) doubles per row (wide false: the scalar loop;
//  the same values)
template<class Index>
void sparseRowProducts
(
    int C,
    std::size_t i0,
    std::size_t i1,
    const std::size_t* outer,
    const Index* inner,
    const double* values,
    const double* a,
    double* v,
    bool wide = true
);

//- Do the wide products use AVX2 for 3 columns on this processor?
bool sparseRowProductsAvx2();

} // namespace dcprbf
