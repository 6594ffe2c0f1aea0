// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "AugmentedKernel.hpp"

#include <algorithm>
#include <cmath>

namespace dcprbf
{

AugmentedKernel::AugmentedKernel
(
    const RadialKernel& kernel,
    const LinearPolynomial& polynomial
)
:
    kernel_(kernel),
    polynomial_(polynomial),
    shift_(0),
    increases_(0)
{
    if (kernel_.needsPolynomial() && !polynomial_.enabled())
    {
        throw Error
        (
            "the " + kernel_.name() + " kernel is only conditionally positive"
            " definite: it needs the linear polynomial"
        );
    }
    shift_ = initialShift();
}


double AugmentedKernel::initialShift() const
{
    if (kernel_.positiveDefinite()) return 0;
    // |xi^2 ln xi| on [0, xiMax]: the interior extremum 1/(2e) at
    // xi = e^(-1/2), or the end value
    const double xiMax = polynomial_.diameter()/kernel_.radius();
    const double atEnd = std::abs(kernel_(polynomial_.diameter()));
    const double interior = xiMax > std::exp(-0.5) ? 0.5/std::exp(1.0) : 0.0;
    return 10*std::max({atEnd, interior, 1e-300});
}


void AugmentedKernel::increaseShift()
{
    if (kernel_.positiveDefinite() || increases_ >= 6)
    {
        throw Error
        (
            "the kernel matrix is not positive definite: control points"
            " closer than round-off allows, or a kernel/radius unfit for this"
            " point set"
        );
    }
    shift_ *= 10;
    ++increases_;
}


double AugmentedKernel::operator()(const double* x, const double* y) const
{
    const double d0 = x[0] - y[0], d1 = x[1] - y[1], d2 = x[2] - y[2];
    double k = kernel_.visit
    (
        [&](const auto& phi) { return phi.ofSquared(d0*d0 + d1*d1 + d2*d2); }
    );
    if (shift_ > 0)
    {
        double qx[4], qy[4];
        polynomial_.basis(x, qx);
        polynomial_.basis(y, qy);
        for (int i = 0; i < polynomial_.size(); ++i) k += shift_*qx[i]*qy[i];
    }
    return k;
}


double AugmentedKernel::diagonal(const double* x) const
{
    return (*this)(x, x);
}


void AugmentedKernel::radialColumn
(
    const Points& x,
    const double* y,
    double* out
) const
{
    AugmentedKernel plain(*this);
    plain.shift_ = 0;
    plain.column(x, y, out);
}


Eigen::MatrixXd AugmentedKernel::radialMatrix
(
    const Points& a,
    const Points& b
) const
{
    AugmentedKernel plain(*this);
    plain.shift_ = 0;
    return plain.matrix(a, b);
}


void AugmentedKernel::column(const Points& x, const double* y, double* out) const
{
    const std::ptrdiff_t n = x.rows();
    const double* px = x.data();
    const int m = shift_ > 0 ? polynomial_.size() : 0;
    double qy[4] = {0, 0, 0, 0};
    polynomial_.basis(y, qy);
    kernel_.visit([&](const auto& phi)
    {
        #pragma omp parallel for schedule(static) if(n > 4096)
        for (std::ptrdiff_t i = 0; i < n; ++i)
        {
            const double* xi = px + 3*i;
            const double d0 = xi[0] - y[0], d1 = xi[1] - y[1], d2 = xi[2] - y[2];
            double k = phi.ofSquared(d0*d0 + d1*d1 + d2*d2);
            if (m > 0)
            {
                double q[4];
                polynomial_.basis(xi, q);
                for (int j = 0; j < m; ++j) k += shift_*q[j]*qy[j];
            }
            out[i] = k;
        }
    });
}


Eigen::MatrixXd AugmentedKernel::matrix(const Points& a, const Points& b) const
{
    Eigen::MatrixXd K(a.rows(), b.rows());
    const std::ptrdiff_t nb = b.rows();
    // one column per iteration; column() itself stays serial for short
    // columns, so this loop is the parallel one
    #pragma omp parallel for schedule(dynamic, 16) if(a.rows() <= 4096)
    for (std::ptrdiff_t j = 0; j < nb; ++j)
    {
        column(a, b.row(j).data(), K.col(j).data());
    }
    return K;
}

} // namespace dcprbf
