// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// StoredEvaluation, continued: the products with the stored matrices (plain,
// patched, and written straight to their targets).
#include "StoredEvaluation.hpp"

#include <cstdint>
#include <string>

namespace dcprbf
{

namespace
{

//- out[0..C) = sum over the row's entries k of values[k]*a[C*inner[k] + .],
//  in four interleaved partial sums (four independent addition chains: with
//  two, the additions' latency bounded the product, 2 cycles per entry)
template<int C, class Index>
inline void rowProduct
(
    std::size_t k,
    const std::size_t end,
    const double* values,
    const Index* inner,
    const double* a,
    double* out
)
{
    constexpr int U = 4;
    double v[U][C] = {};
    for (; k + U - 1 < end; k += U)
    {
        for (int u = 0; u < U; ++u)
        {
            const double* au = a + C*inner[k + u];
            for (int q = 0; q < C; ++q) v[u][q] += values[k + u]*au[q];
        }
    }
    for (; k < end; ++k)
    {
        const double* a0 = a + C*inner[k];
        for (int q = 0; q < C; ++q) v[0][q] += values[k]*a0[q];
    }
    for (int q = 0; q < C; ++q) out[q] = (v[0][q] + v[1][q]) + (v[2][q] + v[3][q]);
}


//- c[C j + q] = m(j, q): m's first C columns, rows 0 .. rows - 1, row by
//  row, contiguous (c sized)
template<int C, class Matrix, class Index>
inline void packColumns(const Matrix& m, const Index rows, std::vector<double>& c)
{
    for (Index j = 0; j < rows; ++j)
    {
        for (int q = 0; q < C; ++q) c[C*j + q] = m(j, q);
    }
}


#if defined(__GNUC__)
//- Each cache line of [from, to) requested now. Called from the row
//  loop itself: GCC 12 (-ffinite-loops) deleted these loops as without
//  effect when a helper of the row's arrays called them (listed rows
//  1.4x slower, cold)
inline void prefetchLines(const void* from, const void* to)
{
    const std::uintptr_t line = 64;
    for
    (
        std::uintptr_t at = reinterpret_cast<std::uintptr_t>(from) & ~(line - 1);
        at < reinterpret_cast<std::uintptr_t>(to);
        at += line
    )
    {
        __builtin_prefetch(reinterpret_cast<const void*>(at));
    }
}
#endif


//- A row's values v to the scatter's targets (row i's), else to row i of
//  out (its 3 columns)
template<class Scatter>
inline void writeRow(const Scatter* scatter, const std::ptrdiff_t i, const double* v, Values& out)
{
    if (scatter)
    {
        scatter->targets.write(std::size_t(i), v, scatter->components, scatter->out);
    }
    else
    {
        out(i, 0) = v[0];
        out(i, 1) = v[1];
        out(i, 2) = v[2];
    }
}


//- The right-hand sides' columns in the product: 2 when the last column of
//  alpha and beta is zero (2D: the normal direction), else 3
int activeColumns(const Values& alpha, const Eigen::MatrixX3d& beta)
{
    return alpha.col(2).isZero(0) && beta.col(2).isZero(0) ? 2 : 3;
}

//- v[0..C) = row i of the slot's compact matrix times a (alpha packed),
//  by the width of its columns
template<int C, class Slot>
inline void compactRow(const Slot& s, const std::ptrdiff_t i, const double* a, double* v)
{
    const std::size_t k = s.outer[i], end = s.outer[i + 1];
    if (!s.inner8.empty())
    {
        rowProduct<C>(k, end, s.values.data(), s.inner8.data(), a, v);
    }
    else if (!s.inner.empty())
    {
        rowProduct<C>(k, end, s.values.data(), s.inner.data(), a, v);
    }
    else
    {
        rowProduct<C>(k, end, s.values.data(), s.inner32.data(), a, v);
    }
}


//- v += Q(x_i) beta: the constant (times 1, exactly), then the rest (qi:
//  row i's L columns of Q after the ones, b: beta packed, P rows)
template<int C>
inline void addPolynomial
(
    const double* qi,
    const int L,
    const int P,
    const double* b,
    double* v
)
{
    for (int q = 0; P > 0 && q < C; ++q) v[q] += b[q];
    for (int p = 0; p < L; ++p)
    {
        for (int q = 0; q < C; ++q) v[q] += qi[p]*b[C*(p + 1) + q];
    }
}


//- v += the patch's columns of row pi (those of this row, in the patch's
//  order; none without pStart)
template<int C>
inline void addPatchColumns
(
    const std::uint32_t* pStart,
    const std::ptrdiff_t pi,
    const std::uint8_t* pEntry,
    const double* pValue,
    const double* patchWeights,
    double* v
)
{
    for (std::uint32_t k = pStart ? pStart[pi] : 0, end = pStart ? pStart[pi + 1] : 0; k < end; ++k)
    {
        const double* w = patchWeights + C*pEntry[k];
        for (int q = 0; q < C; ++q) v[q] += pValue[k]*w[q];
    }
}

} // namespace


template<int C>
void StoredEvaluation::product
(
    const Slot& s,
    const Values& alpha,
    const Eigen::MatrixX3d& beta,
    Values& out,
    const Scatter* scatter,
    const double* patchWeights,
    const std::vector<int>* rows,
    const Patch& patch,
    const bool byPosition
) const
{
    // every row, or the rows listed (the same operations on each row)
    const std::ptrdiff_t n = rows ? std::ptrdiff_t(rows->size()) : x_.rows();
    const int* row = rows ? rows->data() : nullptr;
    const std::uint32_t* pStart = patchWeights ? patch.start.data() : nullptr;
    const std::uint8_t* pEntry = patch.entry.data();
    const double* pValue = patch.value.data();
    const int P = polynomial_.size();
    const int L = int(basis_.cols());   // P - 1: Q's columns after the ones
    // alpha and beta with C columns, contiguous
    std::vector<double> a(C*alpha.rows()), b(C*P);
    packColumns<C>(alpha, alpha.rows(), a);
    packColumns<C>(beta, P, b);
    if (s.dense.size())
    {
        out.noalias() = s.dense*alpha;
    }
    // threads for a product worth waking them: a short one (the boundary
    // error at the candidates) costs microseconds, waking a sleeping
    // thread up to a few hundred
    const std::size_t entries = s.dense.size() ? s.dense.size() : s.values.size();
    const bool threads = rows ? n >= minParallelRows : entries >= minParallelEntries;
    #pragma omp parallel for schedule(static) if(threads)
    for (std::ptrdiff_t r = 0; r < n; ++r)
    {
        const std::ptrdiff_t i = row ? row[r] : r;
        #if defined(__GNUC__)
        if (row && r + 2 < n && !s.dense.size())
        {
            // listed rows: the row after next's entries requested now
            // (scattered rows defeat the hardware's prefetch), each cache
            // line of its values and columns
            const std::size_t k = s.outer[row[r + 2]], e = s.outer[row[r + 2] + 1];
            prefetchLines(s.values.data() + k, s.values.data() + e);
            if (!s.inner.empty()) prefetchLines(s.inner.data() + k, s.inner.data() + e);
            else if (!s.inner8.empty()) prefetchLines(s.inner8.data() + k, s.inner8.data() + e);
            else if (!s.inner32.empty()) prefetchLines(s.inner32.data() + k, s.inner32.data() + e);
        }
        #endif
        double v[3] = {0, 0, 0};
        if (s.dense.size())
        {
            for (int q = 0; q < C; ++q) v[q] = out(i, q);
        }
        else
        {
            compactRow<C>(s, i, a.data(), v);
        }
        addPolynomial<C>(basis_.data() + std::ptrdiff_t(L)*i, L, P, b.data(), v);
        addPatchColumns<C>
        (
            pStart, byPosition ? r : i, pEntry, pValue, patchWeights, v
        );
        writeRow(scatter, i, v, out);
    }
}


void StoredEvaluation::checkTargets
(
    const Targets& targets,
    const std::vector<int>* rows
) const
{
    if (targets.start.size() != std::size_t(x_.rows()) + 1)
    {
        throw Error
        (
            "StoredEvaluation::evaluateInto: targets for "
          + std::to_string(targets.start.size() - 1) + " rows, the matrix has "
          + std::to_string(x_.rows())
        );
    }
    for (std::size_t k = 0; rows && k < rows->size(); ++k)
    {
        if ((*rows)[k] < 0 || (*rows)[k] >= x_.rows())
        {
            throw Error
            (
                "StoredEvaluation::evaluateInto: row " + std::to_string((*rows)[k])
              + " of a matrix of " + std::to_string(x_.rows()) + " rows"
            );
        }
    }
}


bool StoredEvaluation::evaluateInto
(
    const Values& alpha,
    const Eigen::MatrixX3d& beta,
    const Targets& targets,
    const int components,
    double* out,
    const std::vector<int>* rows
) const
{
    checkTargets(targets, rows);
    if (current_ < 0 && patch_.base < 0)
    {
        return false;
    }
    const Slot& s = slots_[patch_.base < 0 ? current_ : patch_.base];
    if (s.dense.size())
    {
        return false;
    }
    const Scatter scatter{targets, components, out};
    Values unused;
    productOf(s, alpha, beta, unused, &scatter, rows);
    return true;
}


Values StoredEvaluation::slotWeights
(
    const Slot& s,
    const Patch& patch,
    const Values& alpha
) const
{
    // the shared centres through the stored matrix (zero for the slot's
    // centres the set no longer has; a centre given twice: both weights on
    // its column), the others alone
    Values a = Values::Zero(s.centres.rows(), 3);
    for (std::size_t j = 0; j < patch.column.size(); ++j)
    {
        if (patch.column[j] >= 0)
        {
            a.row(patch.column[j]) += alpha.row(j);
        }
    }
    return a;
}


void StoredEvaluation::productOf
(
    const Slot& s,
    const Values& alpha,
    const Eigen::MatrixX3d& beta,
    Values& out,
    const Scatter* scatter,
    const std::vector<int>* rows
) const
{
    productOf(s, patch_, false, alpha, beta, out, scatter, rows);
}


void StoredEvaluation::productOf
(
    const Slot& s,
    const Patch& patch,
    const bool byPosition,
    const Values& alpha,
    const Eigen::MatrixX3d& beta,
    Values& out,
    const Scatter* scatter,
    const std::vector<int>* rows
) const
{
    // a patched set's weights in the slot's columns, and its own columns'
    // weights (C contiguous per column)
    const bool patched = patch.base >= 0;
    const Values a = patched ? slotWeights(s, patch, alpha) : Values();
    const Values& as = patched ? a : alpha;
    const int C = activeColumns(alpha, beta);
    std::vector<double> w(C*patch.centre.size());
    for (std::size_t e = 0; e < patch.centre.size(); ++e)
    {
        for (int q = 0; q < C; ++q) w[C*e + q] = alpha(patch.centre[e], q);
    }
    const double* pw = patched && !w.empty() ? w.data() : nullptr;
    if (C == 2)
    {
        product<2>(s, as, beta, out, scatter, pw, rows, patch, byPosition);
    }
    else
    {
        product<3>(s, as, beta, out, scatter, pw, rows, patch, byPosition);
    }
}


void StoredEvaluation::evaluate
(
    const Values& alpha,
    const Eigen::MatrixX3d& beta,
    Values& out
) const
{
    out.resize(x_.rows(), 3);
    productOf(slots_[patch_.base < 0 ? current_ : patch_.base], alpha, beta, out);
}


std::size_t StoredEvaluation::bytes() const
{
    return slots_[0].bytes() + slots_[1].bytes() + patch_.bytes();
}

} // namespace dcprbf
