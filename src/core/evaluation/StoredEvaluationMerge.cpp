// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// StoredEvaluation, continued: a set too far from a stored one for a patch
// made from it all the same (its shared columns' entries copied, the new
// centres' columns computed) instead of built anew.
#include "StoredEvaluation.hpp"
#include "PointTree.hpp"

#include <map>
#include <memory>
#include <numeric>
#include <type_traits>

namespace dcprbf
{

namespace
{

//- f(columns) with a slot's column array, whichever width it is stored in
template<class Inner8, class Inner16, class Inner32, class F>
inline void withColumns(Inner8& inner8, Inner16& inner, Inner32& inner32, int bytes, F f)
{
    if (bytes == 1)
    {
        f(inner8.data());
    }
    else if (bytes == 2)
    {
        f(inner.data());
    }
    else
    {
        f(inner32.data());
    }
}

} // namespace


StoredEvaluation::Merge StoredEvaluation::merge
(
    const int k,
    const Points& c,
    const std::size_t budget,
    Slot& s
) const
{
    const Slot& from = slots_[k];
    if (!kernel_.compact() || !from.used || from.centres.rows() == 0)
    {
        return Merge::notWorth;
    }
    // The new set's column of each of the slot's centres (-1: gone; a
    // centre given twice is copied into its first column, computed anew
    // for the others) and the centres it has not
    const std::map<std::array<double, 3>, int> columnOf(rowsOf(from.centres));
    std::vector<int> newColumn(from.centres.rows(), -1);
    std::vector<int> fresh;
    for (Eigen::Index j = 0; j < c.rows(); ++j)
    {
        const auto it = columnOf.find({c(j, 0), c(j, 1), c(j, 2)});
        if (it != columnOf.end() && newColumn[it->second] < 0)
        {
            newColumn[it->second] = int(j);
        }
        else
        {
            fresh.push_back(int(j));
        }
    }
    // worth it while most of the columns are copied
    if (2*fresh.size() > std::size_t(c.rows()))
    {
        return Merge::notWorth;
    }

    const std::ptrdiff_t n = x_.rows();
    Points cNew(fresh.size(), 3);
    for (std::size_t e = 0; e < fresh.size(); ++e) cNew.row(e) = c.row(fresh[e]);
    const double R = kernel_.radius(), R2 = R*R;
    // the fresh columns: each row's in the order of fresh (few of them), or
    // the tree's
    const bool useTree = fresh.size() > std::size_t(maxPatchColumns);
    const std::unique_ptr<PointTree> tree(useTree ? new PointTree(cNew) : nullptr);
    const int fromBytes =
        !from.inner8.empty() ? 1 : !from.inner.empty() ? 2 : 4;
    const auto fromColumns = [&](auto f)
    {
        withColumns(from.inner8, from.inner, from.inner32, fromBytes, f);
    };

    // a pass to count, a pass to fill (as build()), into s's storage (its
    // matrix is replaced: no fresh pages while it has room, see size below)
    std::vector<std::size_t>& count = s.outer;
    count.assign(n + 1, 0);
    fromColumns([&](const auto* in)
    {
        kernel_.visit([&](const auto& phi)
        {
            #pragma omp parallel for schedule(static) if(n >= minParallelRows)
            for (std::ptrdiff_t i = 0; i < n; ++i)
            {
                std::size_t m = 0;
                for (std::size_t q = from.outer[i]; q < from.outer[i + 1]; ++q)
                {
                    m += newColumn[in[q]] >= 0;
                }
                if (useTree)
                {
                    tree->forEachWithin(&x_(i, 0), R, [&](std::size_t, double) { ++m; });
                }
                else
                {
                    m += newEntries(phi, R2, &x_(i, 0), cNew, [](std::size_t, double) {});
                }
                count[i + 1] = m;
            }
        });
    });
    std::partial_sum(count.begin(), count.end(), count.begin());
    const std::size_t nnz = count.back();
    const int indexBytes = c.rows() <= 256 ? 1 : c.rows() <= 65536 ? 2 : 4;
    if ((n + 1)*sizeof(std::size_t) + nnz*(indexBytes + sizeof(double)) > budget)
    {
        return Merge::tooBig;
    }
    // storage grown with a little room, counted in bytes(); unused widths
    // released
    const std::size_t extra = room(n, nnz, indexBytes, budget);
    const auto size = [nnz, extra](auto& v, bool used)
    {
        const std::size_t m = used ? nnz : 0;
        if (m > v.capacity() || v.capacity() > m + extra)
        {
            std::remove_reference_t<decltype(v)> grown;
            grown.reserve(m + (used ? extra : 0));
            v.swap(grown);
        }
        v.resize(m);
        if (!used) v.shrink_to_fit();
    };
    size(s.inner8, indexBytes == 1);
    size(s.inner, indexBytes == 2);
    size(s.inner32, indexBytes == 4);
    size(s.values, true);
    s.dense.resize(0, 0);

    fromColumns([&](const auto* in)
    {
        withColumns(s.inner8, s.inner, s.inner32, indexBytes, [&](auto* out)
        {
            using Out = std::remove_reference_t<decltype(*out)>;
            double* value = s.values.data();
            kernel_.visit([&](const auto& phi)
            {
                #pragma omp parallel for schedule(static) if(n >= minParallelRows)
                for (std::ptrdiff_t i = 0; i < n; ++i)
                {
                    // the shared centres' entries, in the slot's order,
                    // then the fresh ones
                    std::size_t at = s.outer[i];
                    const auto put = [&](const int j, const double v)
                    {
                        out[at] = Out(j);
                        value[at++] = v;
                    };
                    for (std::size_t q = from.outer[i]; q < from.outer[i + 1]; ++q)
                    {
                        const int j = newColumn[in[q]];
                        if (j >= 0) put(j, from.values[q]);
                    }
                    if (useTree)
                    {
                        tree->forEachWithin(&x_(i, 0), R, [&](std::size_t e, double d2)
                        {
                            put(fresh[e], phi.ofSquared(d2));
                        });
                    }
                    else
                    {
                        newEntries(phi, R2, &x_(i, 0), cNew, [&](std::size_t e, double v)
                        {
                            put(fresh[e], v);
                        });
                    }
                }
            });
        });
    });
    s.centres = c;
    s.used = true;
    return Merge::merged;
}

} // namespace dcprbf
