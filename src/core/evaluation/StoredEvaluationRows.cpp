// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// StoredEvaluation, continued: a set's values at a few rows as prepare() and
// evaluateInto() would give them, without preparing the set.
#include "StoredEvaluation.hpp"

#include <limits>

namespace dcprbf
{

bool StoredEvaluation::evaluateRowsFor
(
    const Points& centres,
    const std::size_t budgetBytes,
    const Values& alpha,
    const Eigen::MatrixX3d& beta,
    const Targets& targets,
    const int components,
    double* out,
    const std::vector<int>& rows
) const
{
    // as prepare() would: stored as they are (the current patch, or the
    // current slot of these centres), or a patch of the current slot sure
    // to fit the budget (with every row in each new column). Anything else
    // (another slot: prepare() would make it current, and later sets would
    // be patched from it; a set refused before; a build) is prepare()'s
    checkTargets(targets, &rows);
    const Plan pl = plan(centres, budgetBytes);
    if (pl.step == Step::currentPatch)
    {
        return evaluateInto(alpha, beta, targets, components, out, &rows);
    }
    if
    (
        current_ < 0 || slots_[current_].dense.size()
     || (pl.step == Step::slot && pl.slot != current_)
     || pl.step == Step::refused
    )
    {
        return false;
    }
    const Scatter scatter{targets, components, out};
    Values unused;
    if (pl.step == Step::slot)
    {
        // the current slot without a patch
        productOf(slots_[current_], Patch(), false, alpha, beta, unused, &scatter, &rows);
        return true;
    }
    Patch p;
    const std::size_t n = std::size_t(x_.rows());
    if
    (
        !slots_[current_].used || !planPatch(current_, centres, p)
     || patchBytes(p, p.centre.size()*n) > budgetBytes
     || p.centre.size()*n > std::numeric_limits<std::uint32_t>::max()
    )
    {
        return false;
    }

    // the new centres' entries at the listed rows alone, by position, in
    // the order of the patch's centres (as patch() stores them by rows)
    const double R2 = kernel_.compact() ? kernel_.radius()*kernel_.radius() : -1;
    const Points cNew(p.newCentres());
    p.start.assign(rows.size() + 1, 0);
    kernel_.visit([&](const auto& phi)
    {
        for (std::size_t r = 0; r < rows.size(); ++r)
        {
            p.start[r + 1] = p.start[r] + newEntries(phi, R2, &x_(rows[r], 0), cNew,
                [&](const std::size_t e, const double v)
                {
                    p.entry.push_back(std::uint8_t(e));
                    p.value.push_back(v);
                });
        }
    });
    productOf(slots_[current_], p, true, alpha, beta, unused, &scatter, &rows);
    return true;
}

} // namespace dcprbf
