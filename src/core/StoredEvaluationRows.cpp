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
    // the cases of prepare(), in its order. Stored as they are: the current
    // patch, or a slot of these centres
    checkTargets(targets, &rows);
    const auto same = [&](const Points& c)
    {
        return c.rows() == centres.rows() && c == centres;
    };
    if (patch_.base >= 0 && same(patch_.centres))
    {
        return evaluateInto(alpha, beta, targets, components, out, &rows);
    }
    for (int k = 0; k < 2; ++k)
    {
        if (slots_[k].used && same(slots_[k].centres))
        {
            // (the other slot: prepare() would make it current, and later
            // sets would be patched from it)
            if (k != current_ || slots_[k].dense.size())
            {
                return false;
            }
            // the slot without a patch
            const Scatter scatter{targets, components, out};
            Values unused;
            productOf(slots_[k], Patch(), false, alpha, beta, unused, &scatter, &rows);
            return true;
        }
    }

    // a patch of the current slot, sure to fit the budget (with every row
    // in each new column); anything else is prepare()'s to decide (a set
    // refused before with no more room among it)
    if
    (
        current_ < 0 || !slots_[current_].used || slots_[current_].dense.size()
     || (same(refused_) && budgetBytes <= refusedBudget_)
    )
    {
        return false;
    }
    Patch p;
    if (!planPatch(current_, centres, p))
    {
        return false;
    }
    const std::size_t n = std::size_t(x_.rows());
    const std::size_t nNew = p.centre.size();
    const std::size_t most =
        slots_[0].bytes() + slots_[1].bytes() + p.column.size()*sizeof(int)
      + (nNew ? (n + 1)*sizeof(std::uint32_t) : 0) + nNew*n*(1 + sizeof(double));
    if (most > budgetBytes || nNew*n > std::numeric_limits<std::uint32_t>::max())
    {
        return false;
    }

    // the new centres' entries at the listed rows alone, by position, in
    // the order of the patch's centres (as patch() stores them by rows)
    const double R2 = kernel_.compact() ? kernel_.radius()*kernel_.radius() : -1;
    p.start.assign(rows.size() + 1, 0);
    kernel_.visit([&](const auto& phi)
    {
        for (std::size_t r = 0; r < rows.size(); ++r)
        {
            for (std::size_t e = 0; e < nNew; ++e)
            {
                double value;
                if (entry(phi, R2, &x_(rows[r], 0), &centres(p.centre[e], 0), value))
                {
                    p.entry.push_back(std::uint8_t(e));
                    p.value.push_back(value);
                }
            }
            p.start[r + 1] = std::uint32_t(p.value.size());
        }
    });
    const Scatter scatter{targets, components, out};
    Values unused;
    productOf(slots_[current_], p, true, alpha, beta, unused, &scatter, &rows);
    return true;
}

} // namespace dcprbf
