// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "UpdatableCholesky.hpp"

#include <algorithm>
#include <cmath>

namespace dcprbf
{

void UpdatableCholesky::reserve(Eigen::Index n)
{
    if (n <= L_.rows()) return;
    const Eigen::Index cap = std::max<Eigen::Index>({n, 2*L_.rows(), 16});
    L_.conservativeResize(cap, cap);
}


void UpdatableCholesky::assign(const Eigen::MatrixXd& L)
{
    n_ = 0;
    reserve(L.rows());
    n_ = L.rows();
    L_.topLeftCorner(n_, n_).triangularView<Eigen::Lower>() = L;
}


Eigen::VectorXd UpdatableCholesky::forwardRow(const Eigen::VectorXd& a) const
{
    if (a.size() != n_)
    {
        throw Error("UpdatableCholesky::forwardRow: size mismatch");
    }
    Eigen::VectorXd l = a;
    solveLowerInPlace(l);
    return l;
}


void UpdatableCholesky::append(const Eigen::VectorXd& l, double pivot)
{
    if (l.size() != n_ || !(pivot > 0))
    {
        throw Error("UpdatableCholesky::append: bad row or pivot");
    }
    reserve(n_ + 1);
    L_.row(n_).head(n_) = l.transpose();
    L_(n_, n_) = pivot;
    ++n_;
}


void UpdatableCholesky::remove(Eigen::Index k, Eigen::MatrixXd& attached)
{
    if (k < 0 || k >= n_ || attached.rows() < n_)
    {
        throw Error("UpdatableCholesky::remove: index out of range");
    }
    const Eigen::Index n = n_;
    const Eigen::Index m = attached.cols();

    // x = l32 (the part of column k below the diagonal), z = row k of X
    Eigen::VectorXd x = L_.col(k).segment(k + 1, n - k - 1);
    Eigen::RowVectorXd z = attached.row(k);

    // Columns left of k: delete row k (move rows below it up by one)
    for (Eigen::Index c = 0; c < k; ++c)
    {
        double* col = L_.col(c).data();
        std::copy(col + k + 1, col + n, col + k);
    }

    // Trailing block: rotate column j against x, store it one column left
    // and one row up
    for (Eigen::Index j = k + 1; j < n; ++j)
    {
        const Eigen::Index off = j - k - 1;   // position of row j in x
        const double a = L_(j, j);
        const double b = x(off);
        const double r = std::hypot(a, b);
        const double c = a/r;
        const double s = b/r;

        const double* src = L_.col(j).data();
        double* dst = L_.col(j - 1).data();
        double* xv = x.data();
        for (Eigen::Index i = j; i < n; ++i)
        {
            const double li = src[i];
            const double xi = xv[i - k - 1];
            dst[i - 1] = c*li + s*xi;
            xv[i - k - 1] = c*xi - s*li;
        }

        // the same rotation on the attached rows: row j and z
        for (Eigen::Index d = 0; d < m; ++d)
        {
            const double aj = attached(j, d);
            attached(j - 1, d) = c*aj + s*z(d);
            z(d) = c*z(d) - s*aj;
        }
    }
    --n_;
}

} // namespace dcprbf
