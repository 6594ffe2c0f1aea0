// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "StoredEvaluation.hpp"
#include "PointTree.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <string>

namespace dcprbf
{

std::size_t StoredEvaluation::Slot::bytes() const
{
    return outer.size()*sizeof(std::size_t) + inner8.size()
        + inner.size()*sizeof(std::uint16_t) + inner32.size()*sizeof(int)
        + values.size()*sizeof(double)
        + dense.size()*sizeof(double);
}


StoredEvaluation::StoredEvaluation
(
    const RadialKernel& kernel,
    const LinearPolynomial& polynomial,
    const Points& x
)
:
    kernel_(kernel),
    polynomial_(polynomial),
    x_(x),
    // Q(x) but its column of ones (8 bytes a row fewer to stream)
    basis_(polynomial.basis(x).rightCols(std::max(0, polynomial.size() - 1)))
{}


bool StoredEvaluation::build(const Points& c, std::size_t budget, Slot& s) const
{
    s = Slot();
    const std::ptrdiff_t n = x_.rows();
    if (!kernel_.compact())
    {
        if (std::size_t(n)*c.rows()*sizeof(double) > budget) return false;
        s.dense.resize(n, c.rows());
        kernel_.visit([&](const auto& phi)
        {
            #pragma omp parallel for schedule(static)
            for (std::ptrdiff_t i = 0; i < n; ++i)
            {
                for (Eigen::Index j = 0; j < c.rows(); ++j)
                {
                    s.dense(i, j) = phi.ofSquared((x_.row(i) - c.row(j)).squaredNorm());
                }
            }
        });
    }
    else
    {
        // two passes over a tree of the centres: count, then fill
        const PointTree tree(c);
        const double R = kernel_.radius();
        std::vector<std::size_t> count(n + 1, 0);
        #pragma omp parallel for schedule(dynamic, 256)
        for (std::ptrdiff_t i = 0; i < n; ++i)
        {
            std::size_t k = 0;
            tree.forEachWithin(x_.row(i).data(), R, [&](std::size_t, double) { ++k; });
            count[i + 1] = k;
        }
        std::partial_sum(count.begin(), count.end(), count.begin());
        const std::size_t nnz = count.back();
        // columns in 8 bits up to 256 centres, 16 up to 65536, else 32
        const int indexBytes = c.rows() <= 256 ? 1 : c.rows() <= 65536 ? 2 : 4;
        if ((n + 1)*sizeof(std::size_t) + nnz*(indexBytes + sizeof(double)) > budget)
        {
            return false;
        }
        s.outer = std::move(count);
        s.inner8.resize(indexBytes == 1 ? nnz : 0);
        s.inner.resize(indexBytes == 2 ? nnz : 0);
        s.inner32.resize(indexBytes == 4 ? nnz : 0);
        s.values.resize(nnz);
        kernel_.visit([&](const auto& phi)
        {
            #pragma omp parallel for schedule(dynamic, 256)
            for (std::ptrdiff_t i = 0; i < n; ++i)
            {
                std::size_t k = s.outer[i];
                tree.forEachWithin(x_.row(i).data(), R, [&](std::size_t j, double d2)
                {
                    if (indexBytes == 1)
                    {
                        s.inner8[k] = std::uint8_t(j);
                    }
                    else if (indexBytes == 2)
                    {
                        s.inner[k] = std::uint16_t(j);
                    }
                    else
                    {
                        s.inner32[k] = int(j);
                    }
                    s.values[k++] = phi.ofSquared(d2);
                });
            }
        });
    }
    s.centres = c;
    s.used = true;
    return true;
}


bool StoredEvaluation::prepare(const Points& centres, std::size_t budgetBytes)
{
    const auto same = [&](const Points& c)
    {
        return c.rows() == centres.rows() && c == centres;
    };
    if (patch_.base >= 0 && same(patch_.centres))
    {
        return true;
    }
    for (int k = 0; k < 2; ++k)
    {
        const Slot& s = slots_[k];
        if (s.used && same(s.centres))
        {
            current_ = k;
            patch_ = Patch();
            return true;
        }
    }
    // refused before with no more room: refused again at once (a step
    // whose set does not fit does not pay the count pass again)
    if (same(refused_) && budgetBytes <= refusedBudget_)
    {
        current_ = -1;
        patch_ = Patch();
        return false;
    }
    // a patch of the current slot, else of the other
    for (const int k : {current_, 1 - current_})
    {
        if (k >= 0 && k < 2 && slots_[k].used && patch(k, centres, budgetBytes))
        {
            current_ = k;
            return true;
        }
    }
    // into the slot that is not current; the other one counts in the budget
    patch_ = Patch();
    const int k = current_ == 0 ? 1 : 0;
    const std::size_t other = slots_[1 - k].bytes();
    current_ = -1;
    ++attempts_;
    if (other > budgetBytes || !build(centres, budgetBytes - other, slots_[k]))
    {
        slots_[k] = Slot();
        refused_ = centres;
        refusedBudget_ = budgetBytes;
        return false;
    }
    refused_.resize(0, 3);
    ++builds_;
    current_ = k;
    return true;
}


std::size_t StoredEvaluation::Patch::bytes() const
{
    std::size_t b = (column.size() + centre.size())*sizeof(int);
    for (std::size_t e = 0; e < rows.size(); ++e)
    {
        b += rows[e].size()*sizeof(int) + values[e].size()*sizeof(double);
    }
    return b;
}


bool StoredEvaluation::patch(int k, const Points& c, std::size_t budget)
{
    const Slot& s = slots_[k];
    std::map<std::array<double, 3>, int> columnOf;
    for (Eigen::Index j = 0; j < s.centres.rows(); ++j)
    {
        columnOf[{s.centres(j, 0), s.centres(j, 1), s.centres(j, 2)}] = int(j);
    }
    Patch p;
    p.column.assign(c.rows(), -1);
    Eigen::Index shared = 0;
    for (Eigen::Index j = 0; j < c.rows(); ++j)
    {
        const auto it = columnOf.find({c(j, 0), c(j, 1), c(j, 2)});
        if (it != columnOf.end())
        {
            p.column[j] = it->second;
            ++shared;
        }
        else
        {
            p.centre.push_back(int(j));
        }
    }
    if
    (
        int(p.centre.size()) > maxPatchColumns
     || s.centres.rows() - shared > maxPatchColumns
    )
    {
        return false;
    }

    // the new centres' columns, alone
    const double R2 = kernel_.compact() ? kernel_.radius()*kernel_.radius() : -1;
    std::size_t bytes = s.bytes() + slots_[1 - k].bytes() + p.column.size()*sizeof(int);
    const std::ptrdiff_t n = x_.rows();
    std::vector<double> column;
    std::vector<char> within;
    for (const int j : p.centre)
    {
        // a column the current patch has (a trial swap after another): kept
        const Patch& old = patch_;
        std::size_t e = 0;
        while (e < old.centre.size() && old.centres.row(old.centre[e]) != c.row(j)) ++e;
        if (e < old.centre.size())
        {
            bytes += old.rows[e].size()*(sizeof(int) + sizeof(double));
            if (bytes > budget)
            {
                return false;
            }
            p.rows.push_back(old.rows[e]);
            p.values.push_back(old.values[e]);
            continue;
        }
        // else the kernel at every point within R (threads), then those
        // entries in ascending rows
        column.resize(n);
        within.resize(n);
        kernel_.visit([&](const auto& phi)
        {
            #pragma omp parallel for schedule(static) if(n >= minParallelRows)
            for (std::ptrdiff_t i = 0; i < n; ++i)
            {
                const double d2 = (x_.row(i) - c.row(j)).squaredNorm();
                within[i] = R2 < 0 || d2 < R2;
                column[i] = within[i] ? phi.ofSquared(d2) : 0.0;
            }
        });
        std::vector<int> rows;
        std::vector<double> values;
        for (std::ptrdiff_t i = 0; i < n; ++i)
        {
            if (within[i])
            {
                rows.push_back(int(i));
                values.push_back(column[i]);
            }
        }
        bytes += rows.size()*(sizeof(int) + sizeof(double));
        if (bytes > budget)
        {
            return false;
        }
        p.rows.push_back(std::move(rows));
        p.values.push_back(std::move(values));
    }
    p.centres = c;
    p.base = k;
    patch_ = std::move(p);
    return true;
}


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


//- The right-hand sides' columns in the product: 2 when the last column of
//  alpha and beta is zero (2D: the normal direction), else 3
int activeColumns(const Values& alpha, const Eigen::MatrixX3d& beta)
{
    return alpha.col(2).isZero(0) && beta.col(2).isZero(0) ? 2 : 3;
}

} // namespace


template<int C>
void StoredEvaluation::product
(
    const Slot& s,
    const Values& alpha,
    const Eigen::MatrixX3d& beta,
    Values& out,
    const Scatter* scatter
) const
{
    const std::ptrdiff_t n = x_.rows();
    const int P = polynomial_.size();
    const int L = int(basis_.cols());   // P - 1: Q's columns after the ones
    // alpha and beta with C columns, contiguous
    std::vector<double> a(C*alpha.rows()), b(C*P);
    for (Eigen::Index j = 0; j < alpha.rows(); ++j)
    {
        for (int q = 0; q < C; ++q) a[C*j + q] = alpha(j, q);
    }
    for (int p = 0; p < P; ++p)
    {
        for (int q = 0; q < C; ++q) b[C*p + q] = beta(p, q);
    }
    if (s.dense.size())
    {
        out.noalias() = s.dense*alpha;
    }
    // threads for a product worth waking them: a short one (the boundary
    // error at the candidates) costs microseconds, waking a sleeping
    // thread up to a few hundred
    const std::size_t entries = s.dense.size() ? s.dense.size() : s.values.size();
    #pragma omp parallel for schedule(static) if(entries >= minParallelEntries)
    for (std::ptrdiff_t i = 0; i < n; ++i)
    {
        double v[3] = {0, 0, 0};
        if (s.dense.size())
        {
            for (int q = 0; q < C; ++q) v[q] = out(i, q);
        }
        else
        {
            const std::size_t k = s.outer[i], end = s.outer[i + 1];
            if (!s.inner8.empty())
            {
                rowProduct<C>(k, end, s.values.data(), s.inner8.data(), a.data(), v);
            }
            else if (!s.inner.empty())
            {
                rowProduct<C>(k, end, s.values.data(), s.inner.data(), a.data(), v);
            }
            else
            {
                rowProduct<C>(k, end, s.values.data(), s.inner32.data(), a.data(), v);
            }
        }
        // + Q(x_i) beta: the constant (times 1, exactly), then the rest
        const double* qi = basis_.data() + std::ptrdiff_t(L)*i;
        for (int q = 0; P > 0 && q < C; ++q) v[q] += b[q];
        for (int p = 0; p < L; ++p)
        {
            for (int q = 0; q < C; ++q) v[q] += qi[p]*b[C*(p + 1) + q];
        }
        if (scatter)
        {
            const Targets& t = scatter->targets;
            for (std::size_t k = t.start[i]; k < t.start[i + 1]; ++k)
            {
                double* o = scatter->out + 3*std::size_t(t.point[k]);
                for (int q = 0; q < 3; ++q) o[q] = q < scatter->components ? v[q] : 0.0;
            }
        }
        else
        {
            out(i, 0) = v[0];
            out(i, 1) = v[1];
            out(i, 2) = v[2];
        }
    }
}


bool StoredEvaluation::evaluateInto
(
    const Values& alpha,
    const Eigen::MatrixX3d& beta,
    const Targets& targets,
    const int components,
    double* out
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
    productOf(s, alpha, beta, unused, &scatter);
    // the patch's columns, added to each target of their rows as
    // evaluate() adds them to the rows (the same order: the same bits)
    addPatchColumns(alpha, [&](const std::size_t r, const double v, const double* aj)
    {
        for (std::size_t t = targets.start[r]; t < targets.start[r + 1]; ++t)
        {
            double* o = out + 3*std::size_t(targets.point[t]);
            for (int q = 0; q < components; ++q) o[q] += v*aj[q];
        }
    });
    return true;
}


Values StoredEvaluation::slotWeights(const Slot& s, const Values& alpha) const
{
    // the shared centres through the stored matrix (zero for the slot's
    // centres the set no longer has), the others alone
    Values a = Values::Zero(s.centres.rows(), 3);
    for (std::size_t j = 0; j < patch_.column.size(); ++j)
    {
        if (patch_.column[j] >= 0)
        {
            a.row(patch_.column[j]) = alpha.row(j);
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
    const Scatter* scatter
) const
{
    // a patched set's weights in the slot's columns
    const Values a = patch_.base < 0 ? Values() : slotWeights(s, alpha);
    const Values& as = patch_.base < 0 ? alpha : a;
    if (activeColumns(alpha, beta) == 2)
    {
        product<2>(s, as, beta, out, scatter);
    }
    else
    {
        product<3>(s, as, beta, out, scatter);
    }
}


template<class Add>
void StoredEvaluation::addPatchColumns(const Values& alpha, const Add& add) const
{
    for (std::size_t e = 0; e < patch_.centre.size(); ++e)
    {
        // a column's rows are distinct: threads for a long one
        const double* aj = &alpha(patch_.centre[e], 0);
        const std::vector<int>& rows = patch_.rows[e];
        const std::vector<double>& values = patch_.values[e];
        const std::ptrdiff_t nk = std::ptrdiff_t(rows.size());
        #pragma omp parallel for schedule(static) if(nk >= minParallelRows)
        for (std::ptrdiff_t k = 0; k < nk; ++k)
        {
            add(std::size_t(rows[k]), values[k], aj);
        }
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
    addPatchColumns(alpha, [&](const std::size_t r, const double v, const double* aj)
    {
        for (int q = 0; q < 3; ++q) out(Eigen::Index(r), q) += v*aj[q];
    });
}


std::size_t StoredEvaluation::bytes() const
{
    return slots_[0].bytes() + slots_[1].bytes() + patch_.bytes();
}

} // namespace dcprbf
