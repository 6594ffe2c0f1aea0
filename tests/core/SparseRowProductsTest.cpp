// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the stored products' row kernels: the wide call (AVX2 for 3
// columns where the processor has it) gives the scalar loop's bits, and
// both the sum they stand for.
#include "SparseRowProducts.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

using namespace dcprbf;

namespace
{

//- Rows of 0 .. 40 entries (every remainder of the unrolled loop), columns
//  below nCols, values of both signs and of very different sizes
struct Rows
{
    std::vector<std::size_t> outer{0};
    std::vector<int> inner;
    std::vector<double> values;

    Rows(const std::size_t n, const int nCols, const unsigned seed)
    {
        std::mt19937 gen(seed);
        std::uniform_int_distribution<int> len(0, 40), col(0, nCols - 1), e(-8, 8);
        std::uniform_real_distribution<double> u(-1, 1);
        for (std::size_t i = 0; i < n; ++i)
        {
            const int m = i < 41 ? int(i) : len(gen);
            for (int k = 0; k < m; ++k)
            {
                inner.push_back(col(gen));
                values.push_back(std::ldexp(u(gen), e(gen)));
            }
            outer.push_back(inner.size());
        }
    }

    template<class Index>
    std::vector<Index> innerAs() const
    {
        return std::vector<Index>(inner.begin(), inner.end());
    }
};

template<class Index>
void expectKernelsAgree(const int C, const int nCols)
{
    const std::size_t n = 700;
    const Rows r(n, nCols, 17u + unsigned(C));
    const std::vector<Index> inner(r.innerAs<Index>());
    const int S = sparseRowStride(C);
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(-3, 3);
    std::vector<double> a(S*nCols, 0.0);
    for (int j = 0; j < nCols; ++j)
    {
        for (int q = 0; q < C; ++q) a[S*j + q] = u(gen);
    }
    // the rows in two calls (a block boundary inside)
    std::vector<double> wide(C*n), scalar(C*n);
    for (const bool w : {true, false})
    {
        double* v = w ? wide.data() : scalar.data();
        sparseRowProducts(C, 0, 300, r.outer.data(), inner.data(), r.values.data(), a.data(), v, w);
        sparseRowProducts(C, 300, n, r.outer.data(), inner.data(), r.values.data(), a.data(), v + C*300, w);
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        for (int q = 0; q < C; ++q)
        {
            EXPECT_EQ(wide[C*i + q], scalar[C*i + q]) << "row " << i << " column " << q;
            double sum = 0, mag = 0;
            for (std::size_t k = r.outer[i]; k < r.outer[i + 1]; ++k)
            {
                sum += r.values[k]*a[S*r.inner[k] + q];
                mag += std::abs(r.values[k]*a[S*r.inner[k] + q]);
            }
            EXPECT_NEAR(scalar[C*i + q], sum, 1e-14*mag) << "row " << i;
        }
    }
}

} // namespace


TEST(SparseRowProducts, VectorKernelsGiveTheScalarBits8BitColumns)
{
    expectKernelsAgree<std::uint8_t>(2, 256);
    expectKernelsAgree<std::uint8_t>(3, 256);
}


TEST(SparseRowProducts, VectorKernelsGiveTheScalarBits16BitColumns)
{
    expectKernelsAgree<std::uint16_t>(2, 3000);
    expectKernelsAgree<std::uint16_t>(3, 3000);
}


TEST(SparseRowProducts, VectorKernelsGiveTheScalarBits32BitColumns)
{
    expectKernelsAgree<int>(2, 70000);
    expectKernelsAgree<int>(3, 70000);
}
