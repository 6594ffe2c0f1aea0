// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "StoredEvaluation.hpp"
#include "PointTree.hpp"

#include <array>
#include <map>
#include <numeric>

namespace dcprbf
{

std::size_t StoredEvaluation::Slot::bytes() const
{
    return outer.size()*sizeof(int) + inner.size()*sizeof(int)
        + values.size()*sizeof(double) + dense.size()*sizeof(double);
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
    basis_(polynomial.basis(x))
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
        std::vector<int> count(n + 1, 0);
        #pragma omp parallel for schedule(dynamic, 256)
        for (std::ptrdiff_t i = 0; i < n; ++i)
        {
            int k = 0;
            tree.forEachWithin(x_.row(i).data(), R, [&](std::size_t, double) { ++k; });
            count[i + 1] = k;
        }
        std::partial_sum(count.begin(), count.end(), count.begin());
        const std::size_t nnz = count.back();
        if ((n + 1 + nnz)*sizeof(int) + nnz*sizeof(double) > budget) return false;
        s.outer = std::move(count);
        s.inner.resize(nnz);
        s.values.resize(nnz);
        kernel_.visit([&](const auto& phi)
        {
            #pragma omp parallel for schedule(dynamic, 256)
            for (std::ptrdiff_t i = 0; i < n; ++i)
            {
                int k = s.outer[i];
                tree.forEachWithin(x_.row(i).data(), R, [&](std::size_t j, double d2)
                {
                    s.inner[k] = int(j);
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
    if (other > budgetBytes || !build(centres, budgetBytes - other, slots_[k]))
    {
        slots_[k] = Slot();
        return false;
    }
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
    for (const int j : p.centre)
    {
        std::vector<int> rows;
        std::vector<double> values;
        kernel_.visit([&](const auto& phi)
        {
            for (Eigen::Index i = 0; i < x_.rows(); ++i)
            {
                const double d2 = (x_.row(i) - c.row(j)).squaredNorm();
                if (R2 < 0 || d2 < R2)
                {
                    rows.push_back(int(i));
                    values.push_back(phi.ofSquared(d2));
                }
            }
        });
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


void StoredEvaluation::product(const Slot& s, const Values& alpha, Values& out) const
{
    const std::ptrdiff_t n = x_.rows();
    out.resize(n, 3);
    if (s.dense.size())
    {
        out.noalias() = s.dense*alpha;
        return;
    }
    const double* a = alpha.data();
    #pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i)
    {
        double v[3] = {0, 0, 0};
        for (int k = s.outer[i]; k < s.outer[i + 1]; ++k)
        {
            const double w = s.values[k];
            const double* aj = a + 3*s.inner[k];
            v[0] += w*aj[0];
            v[1] += w*aj[1];
            v[2] += w*aj[2];
        }
        out(i, 0) = v[0];
        out(i, 1) = v[1];
        out(i, 2) = v[2];
    }
}


void StoredEvaluation::evaluate
(
    const Values& alpha,
    const Eigen::MatrixX3d& beta,
    Values& out
) const
{
    if (patch_.base < 0)
    {
        product(slots_[current_], alpha, out);
    }
    else
    {
        // the shared centres through the stored matrix, the others alone
        const Slot& s = slots_[patch_.base];
        Values a = Values::Zero(s.centres.rows(), 3);
        for (std::size_t j = 0; j < patch_.column.size(); ++j)
        {
            if (patch_.column[j] >= 0)
            {
                a.row(patch_.column[j]) = alpha.row(j);
            }
        }
        product(s, a, out);
        for (std::size_t e = 0; e < patch_.centre.size(); ++e)
        {
            const auto aj = alpha.row(patch_.centre[e]);
            const std::vector<int>& rows = patch_.rows[e];
            const std::vector<double>& values = patch_.values[e];
            for (std::size_t k = 0; k < rows.size(); ++k)
            {
                out.row(rows[k]) += values[k]*aj;
            }
        }
    }
    if (basis_.cols() > 0)
    {
        out.noalias() += basis_*beta;
    }
}


std::size_t StoredEvaluation::bytes() const
{
    return slots_[0].bytes() + slots_[1].bytes() + patch_.bytes();
}

} // namespace dcprbf
