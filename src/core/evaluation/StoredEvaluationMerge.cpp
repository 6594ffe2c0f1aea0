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


//- v sized to nnz entries with up to extra more reserved (used false: to
//  none, released); storage that would have to grow, or holds more than
//  that room, is replaced
template<class Vector>
inline void resizeWithRoom(Vector& v, const bool used, const std::size_t nnz, const std::size_t extra)
{
    const std::size_t m = used ? nnz : 0;
    if (m > v.capacity() || v.capacity() > m + extra)
    {
        Vector grown;
        grown.reserve(m + (used ? extra : 0));
        v.swap(grown);
    }
    v.resize(m);
    if (!used) v.shrink_to_fit();
}

} // namespace


//- merge()'s plan: the new set's column of each of the slot's centres
//  (-1: gone), the new set's columns the slot has not (fresh) and their
//  centres, with a tree of them when they are more than a patch's
struct StoredEvaluation::MergePlan
{
    std::vector<int> newColumn;
    std::vector<int> fresh;
    Points cNew;
    std::unique_ptr<PointTree> tree;
    int fromBytes = 4;              // the slot's column width in bytes
};


bool StoredEvaluation::planMerge
(
    const int k,
    const Points& c,
    MergePlan& p
) const
{
    const Slot& from = slots_[k];
    if (!kernel_.compact() || !from.used || from.centres.rows() == 0)
    {
        return false;
    }
    // The new set's column of each of the slot's centres (-1: gone; a
    // centre given twice is copied into its first column, computed anew
    // for the others) and the centres it has not
    const std::map<std::array<double, 3>, int> columnOf(rowsOf(from.centres));
    p.newColumn.assign(from.centres.rows(), -1);
    p.fresh.clear();
    for (Eigen::Index j = 0; j < c.rows(); ++j)
    {
        const auto it = columnOf.find({c(j, 0), c(j, 1), c(j, 2)});
        if (it != columnOf.end() && p.newColumn[it->second] < 0)
        {
            p.newColumn[it->second] = int(j);
        }
        else
        {
            p.fresh.push_back(int(j));
        }
    }
    // worth it while most of the columns are copied
    if (2*p.fresh.size() > std::size_t(c.rows()))
    {
        return false;
    }

    p.cNew.resize(p.fresh.size(), 3);
    for (std::size_t e = 0; e < p.fresh.size(); ++e) p.cNew.row(e) = c.row(p.fresh[e]);
    // the fresh columns: each row's in the order of fresh (few of them), or
    // the tree's
    const bool useTree = p.fresh.size() > std::size_t(maxPatchColumns);
    p.tree.reset(useTree ? new PointTree(p.cNew) : nullptr);
    p.fromBytes = !from.inner8.empty() ? 1 : !from.inner.empty() ? 2 : 4;
    return true;
}


void StoredEvaluation::countMerged
(
    const Slot& from,
    const MergePlan& p,
    std::vector<std::size_t>& count
) const
{
    const std::ptrdiff_t n = x_.rows();
    const double R = kernel_.radius(), R2 = R*R;
    const std::vector<int>& newColumn = p.newColumn;
    const Points& cNew = p.cNew;
    const PointTree* tree = p.tree.get();
    withColumns(from.inner8, from.inner, from.inner32, p.fromBytes, [&](const auto* in)
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
                if (tree)
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
}


void StoredEvaluation::sizeStorage
(
    Slot& s,
    const std::size_t nnz,
    const int indexBytes,
    const std::size_t extra
)
{
    resizeWithRoom(s.inner8, indexBytes == 1, nnz, extra);
    resizeWithRoom(s.inner, indexBytes == 2, nnz, extra);
    resizeWithRoom(s.inner32, indexBytes == 4, nnz, extra);
    resizeWithRoom(s.values, true, nnz, extra);
    s.dense.resize(0, 0);
}


void StoredEvaluation::fillMerged
(
    const Slot& from,
    const MergePlan& p,
    const int indexBytes,
    Slot& s
) const
{
    const std::ptrdiff_t n = x_.rows();
    const double R = kernel_.radius(), R2 = R*R;
    const std::vector<int>& newColumn = p.newColumn;
    const std::vector<int>& fresh = p.fresh;
    const Points& cNew = p.cNew;
    const PointTree* tree = p.tree.get();
    withColumns(from.inner8, from.inner, from.inner32, p.fromBytes, [&](const auto* in)
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
                    if (tree)
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
}


StoredEvaluation::Merge StoredEvaluation::merge
(
    const int k,
    const Points& c,
    const std::size_t budget,
    Slot& s
) const
{
    MergePlan p;
    if (!planMerge(k, c, p))
    {
        return Merge::notWorth;
    }
    const Slot& from = slots_[k];
    const std::ptrdiff_t n = x_.rows();

    // a pass to count, a pass to fill (as build()), into s's storage (its
    // matrix is replaced: no fresh pages while it has room, see
    // sizeStorage)
    std::vector<std::size_t>& count = s.outer;
    count.assign(n + 1, 0);
    countMerged(from, p, count);
    std::partial_sum(count.begin(), count.end(), count.begin());
    const std::size_t nnz = count.back();
    const int indexBytes = c.rows() <= 256 ? 1 : c.rows() <= 65536 ? 2 : 4;
    if ((n + 1)*sizeof(std::size_t) + nnz*(indexBytes + sizeof(double)) > budget)
    {
        return Merge::tooBig;
    }
    // storage grown with a little room, counted in bytes(); unused widths
    // released
    sizeStorage(s, nnz, indexBytes, room(n, nnz, indexBytes, budget));
    fillMerged(from, p, indexBytes, s);
    s.centres = c;
    s.used = true;
    return Merge::merged;
}

} // namespace dcprbf
