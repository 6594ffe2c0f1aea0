// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "RbfEvaluator.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>

namespace dcprbf
{

namespace
{
constexpr std::ptrdiff_t pointBlock = 64;
constexpr std::ptrdiff_t centreBlock = 1024;

//- Auto: the tree wins while the query sees less than this fraction of the
//  centres (wing benchmark, WendlandC2: a tree hit costs ~6 ns, a dense
//  pair ~2 ns with SSE2)
constexpr double treeFraction = 0.3;
}


RbfEvaluator::RbfEvaluator
(
    const RadialKernel& kernel,
    const LinearPolynomial& polynomial
)
:
    kernel_(kernel),
    polynomial_(polynomial),
    method_(Method::Auto),
    identity_(nextIdentity())
{}


std::uint64_t RbfEvaluator::nextIdentity()
{
    static std::atomic<std::uint64_t> last{0};
    return ++last;
}


void RbfEvaluator::assign
(
    const Points& centres,
    const Values& alpha,
    const Eigen::MatrixX3d& beta
)
{
    if (alpha.rows() != centres.rows() || beta.rows() != polynomial_.size())
    {
        throw Error
        (
            "RbfEvaluator::assign: " + std::to_string(alpha.rows())
          + " weights and " + std::to_string(beta.rows())
          + " polynomial coefficients for " + std::to_string(centres.rows())
          + " centres and a polynomial of size "
          + std::to_string(polynomial_.size())
        );
    }
    // the same centres (new weights for the same set, every step): the
    // tree of the centres kept
    const bool sameCentres =
        tree_ && centres_.rows() == centres.rows() && centres_ == centres;
    centres_ = centres;
    alpha_ = alpha;
    beta_ = beta;
    identity_ = nextIdentity();

    cx_ = centres.col(0);
    cy_ = centres.col(1);
    cz_ = centres.col(2);
    ax_ = alpha.col(0);
    ay_ = alpha.col(1);
    az_ = alpha.col(2);
    const std::size_t n = centres.rows();
    if (!sameCentres)
    {
        tree_.reset(kernel_.compact() && n > 0 ? new PointTree(centres_) : nullptr);
    }
}


bool RbfEvaluator::usesTree(const double* x, std::size_t n) const
{
    if (!tree_ || method_ == Method::Dense) return false;
    if (method_ == Method::Tree) return true;
    const std::size_t samples = std::min<std::size_t>(n, 64);
    std::size_t hits = 0;
    for (std::size_t s = 0; s < samples; ++s)
    {
        const double* xi = x + 3*((s*n)/samples);
        tree_->forEachWithin(xi, kernel_.radius(), [&](std::size_t, double)
        {
            ++hits;
        });
    }
    return double(hits) <= treeFraction*double(samples*size());
}


void RbfEvaluator::evaluate(const double* x, std::size_t n, double* out) const
{
    if (centres_.rows() == 0)
    {
        throw Error("RBF evaluation without centres and coefficients");
    }
    if (usesTree(x, n))
    {
        evaluateTree(x, n, out);
    }
    else
    {
        evaluateDense(x, n, out);
    }
}


void RbfEvaluator::evaluateRows
(
    const double* x,
    const std::size_t n,
    const std::vector<int>& rows,
    double* out
) const
{
    if (centres_.rows() == 0)
    {
        throw Error("RBF evaluation without centres and coefficients");
    }
    std::vector<double> xr(3*rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k)
    {
        if (rows[k] < 0 || std::size_t(rows[k]) >= n)
        {
            throw Error
            (
                "RbfEvaluator::evaluateRows: point " + std::to_string(rows[k])
              + " of " + std::to_string(n)
            );
        }
        std::copy(x + 3*std::size_t(rows[k]), x + 3*std::size_t(rows[k]) + 3, &xr[3*k]);
    }
    if (usesTree(x, n))
    {
        evaluateTree(xr.data(), rows.size(), out);
    }
    else
    {
        evaluateDense(xr.data(), rows.size(), out);
    }
}


Values RbfEvaluator::evaluate(const Points& x) const
{
    Values out(x.rows(), 3);
    evaluate(x.data(), x.rows(), out.data());
    return out;
}


void RbfEvaluator::addPolynomial(const double* x, double* out) const
{
    if (!polynomial_.enabled()) return;
    double p[3];
    polynomial_.value(x, beta_, p);
    out[0] += p[0];
    out[1] += p[1];
    out[2] += p[2];
}


void RbfEvaluator::evaluateTree(const double* x, std::size_t n, double* out) const
{
    const double R = kernel_.radius();
    kernel_.visit([&](const auto& phi)
    {
        // declared here, not in the enclosing function: clang (14) cannot
        // capture the latter in the inner lambda of this OpenMP loop
        const double* a = alpha_.data();
        #pragma omp parallel for schedule(dynamic, 256)
        for (std::ptrdiff_t i = 0; i < std::ptrdiff_t(n); ++i)
        {
            const double* xi = x + 3*i;
            double s[3] = {0, 0, 0};
            tree_->forEachWithin(xi, R, [&](std::size_t j, double distSq)
            {
                const double w = phi.ofSquared(distSq);
                s[0] += w*a[3*j];
                s[1] += w*a[3*j + 1];
                s[2] += w*a[3*j + 2];
            });
            addPolynomial(xi, s);
            std::copy(s, s + 3, out + 3*i);
        }
    });
}


void RbfEvaluator::evaluateDense(const double* x, std::size_t n, double* out) const
{
    using Block = Eigen::Array<double, Eigen::Dynamic, 1, 0, centreBlock, 1>;
    const std::ptrdiff_t nc = size();
    const std::ptrdiff_t nBlocks = (std::ptrdiff_t(n) + pointBlock - 1)/pointBlock;

    kernel_.visit([&](const auto& phi)
    {
        #pragma omp parallel for schedule(dynamic, 4)
        for (std::ptrdiff_t b = 0; b < nBlocks; ++b)
        {
            const std::ptrdiff_t i0 = b*pointBlock;
            const std::ptrdiff_t i1 = std::min<std::ptrdiff_t>(n, i0 + pointBlock);
            double acc[3*pointBlock] = {};
            Block r2, w;
            for (std::ptrdiff_t j0 = 0; j0 < nc; j0 += centreBlock)
            {
                const std::ptrdiff_t len = std::min(nc - j0, centreBlock);
                const auto cx = cx_.segment(j0, len);
                const auto cy = cy_.segment(j0, len);
                const auto cz = cz_.segment(j0, len);
                const auto ax = ax_.segment(j0, len);
                const auto ay = ay_.segment(j0, len);
                const auto az = az_.segment(j0, len);
                for (std::ptrdiff_t i = i0; i < i1; ++i)
                {
                    const double* xi = x + 3*i;
                    r2 = (cx - xi[0]).square() + (cy - xi[1]).square()
                       + (cz - xi[2]).square();
                    phi.ofSquared(r2, w);
                    double* ai = acc + 3*(i - i0);
                    ai[0] += (w*ax).sum();
                    ai[1] += (w*ay).sum();
                    ai[2] += (w*az).sum();
                }
            }
            for (std::ptrdiff_t i = i0; i < i1; ++i)
            {
                double* oi = out + 3*i;
                std::copy(acc + 3*(i - i0), acc + 3*(i - i0) + 3, oi);
                addPolynomial(x + 3*i, oi);
            }
        }
    });
}


void RbfEvaluator::evaluateBruteForce
(
    const double* x,
    std::size_t n,
    double* out
) const
{
    const Eigen::Index nc = centres_.rows();
    kernel_.visit([&](const auto& phi)
    {
        for (std::size_t i = 0; i < n; ++i)
        {
            const double* xi = x + 3*i;
            double s[3] = {0, 0, 0};
            for (Eigen::Index j = 0; j < nc; ++j)
            {
                const double w = phi
                (
                    (Eigen::Map<const Eigen::RowVector3d>(xi) - centres_.row(j))
                   .norm()
                );
                for (int d = 0; d < 3; ++d) s[d] += w*alpha_(j, d);
            }
            addPolynomial(xi, s);
            std::copy(s, s + 3, out + 3*i);
        }
    });
}

} // namespace dcprbf
