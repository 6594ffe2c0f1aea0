// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "StoredEvaluation.hpp"
#include "PointTree.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <numeric>

namespace dcprbf
{

std::size_t StoredEvaluation::Slot::bytes() const
{
    // (capacities: a merged matrix may hold a little room to grow)
    return outer.capacity()*sizeof(std::size_t) + inner8.capacity()
        + inner.capacity()*sizeof(std::uint16_t) + inner32.capacity()*sizeof(int)
        + values.capacity()*sizeof(double)
        + dense.size()*sizeof(double);
}


std::size_t StoredEvaluation::room
(
    const std::size_t n,
    const std::size_t nnz,
    const int indexBytes,
    const std::size_t budget
)
{
    const std::size_t extra = nnz/32;
    return
        (n + 1)*sizeof(std::size_t) + (nnz + extra)*(indexBytes + sizeof(double)) <= budget
      ? extra : 0;
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


void StoredEvaluation::fillDense(const Points& c, Slot& s) const
{
    const std::ptrdiff_t n = x_.rows();
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


bool StoredEvaluation::buildCompact
(
    const Points& c,
    const std::size_t budget,
    Slot& s
) const
{
    const std::ptrdiff_t n = x_.rows();
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
    // with room: the other slot's merges fill this storage later (if
    // half the budget holds it: the other slot's matrix is to fit
    // beside it, not to be refused for this one's room)
    const std::size_t extra = room(n, nnz, indexBytes, budget/2);
    if (indexBytes == 1) s.inner8.reserve(nnz + extra);
    else if (indexBytes == 2) s.inner.reserve(nnz + extra);
    else s.inner32.reserve(nnz + extra);
    s.values.reserve(nnz + extra);
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
    return true;
}


bool StoredEvaluation::build(const Points& c, std::size_t budget, Slot& s) const
{
    s = Slot();
    const std::ptrdiff_t n = x_.rows();
    if (!kernel_.compact())
    {
        if (std::size_t(n)*c.rows()*sizeof(double) > budget) return false;
        fillDense(c, s);
    }
    else if ((n + 1)*sizeof(std::size_t) > budget)
    {
        // not even the row starts fit: no count pass
        return false;
    }
    else if (!buildCompact(c, budget, s))
    {
        return false;
    }
    s.centres = c;
    s.used = true;
    return true;
}


StoredEvaluation::Plan StoredEvaluation::plan
(
    const Points& centres,
    const std::size_t budgetBytes
) const
{
    const auto same = [&](const Points& c)
    {
        return c.rows() == centres.rows() && c == centres;
    };
    if (patch_.base >= 0 && same(patch_.centres))
    {
        return {Step::currentPatch, current_};
    }
    for (int k = 0; k < 2; ++k)
    {
        if (slots_[k].used && same(slots_[k].centres))
        {
            return {Step::slot, k};
        }
    }
    // refused before with no more room: refused again at once (a step
    // whose set does not fit does not pay the count pass again)
    if (same(refused_) && budgetBytes <= refusedBudget_)
    {
        return {Step::refused};
    }
    return {Step::patchOrBuild};
}


bool StoredEvaluation::prepare(const Points& centres, std::size_t budgetBytes)
{
    const Plan pl = plan(centres, budgetBytes);
    switch (pl.step)
    {
        case Step::currentPatch:
            return true;
        case Step::slot:
            current_ = pl.slot;
            patch_ = Patch();
            return true;
        case Step::refused:
            current_ = -1;
            patch_ = Patch();
            return false;
        case Step::patchOrBuild:
            break;
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
    // into the slot that is not current (none current: one that is not
    // used, if any), merged from the other one or built; the other one
    // counts in the budget. None current (a set refused before): the other
    // one, a set of the past, is dropped rather than this set refused
    patch_ = Patch();
    const bool noneCurrent = current_ < 0;
    const int k =
        !noneCurrent ? 1 - current_ : slots_[0].used && !slots_[1].used ? 1 : 0;
    const std::size_t other = slots_[1 - k].bytes();
    current_ = -1;
    ++attempts_;
    Merge m =
        other > budgetBytes ? Merge::tooBig
      : merge(1 - k, centres, budgetBytes - other, slots_[k]);
    bool made =
        m == Merge::merged
     || (m == Merge::notWorth && build(centres, budgetBytes - other, slots_[k]));
    if (!made && noneCurrent && other > 0)
    {
        slots_[1 - k] = Slot();
        m = Merge::notWorth;
        made = build(centres, budgetBytes, slots_[k]);
    }
    if (!made)
    {
        slots_[k] = Slot();
        refused_ = centres;
        refusedBudget_ = budgetBytes;
        return false;
    }
    refused_.resize(0, 3);
    ++builds_;
    merges_ += m == Merge::merged;
    current_ = k;
    return true;
}


Points StoredEvaluation::Patch::newCentres() const
{
    Points c(centre.size(), 3);
    for (std::size_t e = 0; e < centre.size(); ++e) c.row(e) = centres.row(centre[e]);
    return c;
}


std::size_t StoredEvaluation::patchBytes(const Patch& p, const std::size_t nnz) const
{
    // (the rows' starts only for new columns: a patch that only removes
    // centres has none)
    return
        slots_[0].bytes() + slots_[1].bytes() + p.column.size()*sizeof(int)
      + (p.centre.empty() ? 0 : (std::size_t(x_.rows()) + 1)*sizeof(std::uint32_t))
      + nnz*(1 + sizeof(double));
}


std::size_t StoredEvaluation::Patch::bytes() const
{
    return (column.size() + centre.size())*sizeof(int)
        + start.size()*sizeof(std::uint32_t) + entry.size()
        + value.size()*sizeof(double);
}


std::map<std::array<double, 3>, int> StoredEvaluation::rowsOf(const Points& c)
{
    std::map<std::array<double, 3>, int> row;
    for (Eigen::Index j = 0; j < c.rows(); ++j)
    {
        row.emplace(std::array<double, 3>{c(j, 0), c(j, 1), c(j, 2)}, int(j));
    }
    return row;
}


bool StoredEvaluation::planPatch(int k, const Points& c, Patch& p) const
{
    static_assert(maxPatchColumns <= 256, "a patch entry's column in 8 bits");
    const Slot& s = slots_[k];
    const std::map<std::array<double, 3>, int> columnOf(rowsOf(s.centres));
    p.centres = c;
    p.base = k;
    p.column.assign(c.rows(), -1);
    p.centre.clear();
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
    return
        int(p.centre.size()) <= maxPatchColumns
     && s.centres.rows() - shared <= maxPatchColumns;
}


bool StoredEvaluation::patch(int k, const Points& c, std::size_t budget)
{
    Patch p;
    if (!planPatch(k, c, p))
    {
        return false;
    }
    const std::ptrdiff_t n = x_.rows();
    const std::size_t nNew = p.centre.size();
    std::size_t bytes = patchBytes(p, 0);
    if (bytes > budget)
    {
        return false;
    }
    if (nNew)
    {
        // The new centres' columns by rows, each row's entries in the order
        // of centre: a pass to count them, a pass to fill them (the kernel
        // evaluated again: cheaper than columns gathered and merged). Into
        // the current patch's storage (it is replaced, or prepare() drops
        // it if this fails): no fresh pages for each trial swap's patch
        p.start.swap(patch_.start);
        p.entry.swap(patch_.entry);
        p.value.swap(patch_.value);
        patch_.base = -1;               // (no patch until this one is made)
        p.start.resize(n + 1);
        p.start[0] = 0;
        const Points cNew(p.newCentres());
        const double R2 = kernel_.compact() ? kernel_.radius()*kernel_.radius() : -1;
        std::size_t nnz = 0;
        kernel_.visit([&](const auto& phi)
        {
            #pragma omp parallel for schedule(static) if(n >= minParallelRows)
            for (std::ptrdiff_t i = 0; i < n; ++i)
            {
                p.start[i + 1] = newEntries(phi, R2, &x_(i, 0), cNew, [](std::size_t, double) {});
            }
            for (std::ptrdiff_t i = 0; i < n; ++i)
            {
                nnz += p.start[i + 1];
                p.start[i + 1] = std::uint32_t(nnz);
            }
            bytes = patchBytes(p, nnz);
            if (bytes > budget || nnz > std::numeric_limits<std::uint32_t>::max())
            {
                return;
            }
            p.entry.resize(nnz);
            p.value.resize(nnz);
            #pragma omp parallel for schedule(static) if(n >= minParallelRows)
            for (std::ptrdiff_t i = 0; i < n; ++i)
            {
                std::uint32_t at = p.start[i];
                newEntries(phi, R2, &x_(i, 0), cNew, [&](const std::size_t e, const double v)
                {
                    p.entry[at] = std::uint8_t(e);
                    p.value[at++] = v;
                });
            }
        });
        if (bytes > budget || nnz > std::numeric_limits<std::uint32_t>::max())
        {
            return false;
        }
    }
    patch_ = std::move(p);
    return true;
}

} // namespace dcprbf
