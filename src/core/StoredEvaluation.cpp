// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "StoredEvaluation.hpp"
#include "PointTree.hpp"

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
    for (int k = 0; k < 2; ++k)
    {
        const Slot& s = slots_[k];
        if (s.used && s.centres.rows() == centres.rows() && s.centres == centres)
        {
            current_ = k;
            return true;
        }
    }
    // into the slot that is not current; the other one counts in the budget
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


void StoredEvaluation::evaluate
(
    const Values& alpha,
    const Eigen::MatrixX3d& beta,
    Values& out
) const
{
    const Slot& s = slots_[current_];
    const std::ptrdiff_t n = x_.rows();
    out.resize(n, 3);
    if (s.dense.size())
    {
        out.noalias() = s.dense*alpha;
    }
    else
    {
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
    if (basis_.cols() > 0)
    {
        out.noalias() += basis_*beta;
    }
}


std::size_t StoredEvaluation::bytes() const
{
    return slots_[0].bytes() + slots_[1].bytes();
}

} // namespace dcprbf
