#include "RbfInterpolant.hpp"

#include <Eigen/SVD>

#include <cmath>
#include <sstream>

namespace dcprbf
{

RbfInterpolant::RbfInterpolant
(
    const RadialKernel& kernel,
    bool polynomial,
    int dim
)
:
    kernel_(kernel),
    polynomial_(polynomial),
    dim_(dim),
    shift_(Eigen::RowVector3d::Zero()),
    invScale_(1)
{
    if (dim != 2 && dim != 3)
    {
        throw Error("dimension must be 2 or 3, got " + std::to_string(dim));
    }
    if (kernel_.needsPolynomial() && !polynomial_)
    {
        throw Error
        (
            "the " + kernel_.name() + " kernel is only conditionally positive"
            " definite: it needs the linear polynomial"
        );
    }
}


Eigen::MatrixXd RbfInterpolant::polynomialBasis(const Points& x) const
{
    if (!polynomial_)
    {
        return Eigen::MatrixXd(x.rows(), 0);
    }
    Eigen::MatrixXd P(x.rows(), dim_ + 1);
    P.col(0).setOnes();
    for (int k = 0; k < dim_; ++k)
    {
        P.col(k + 1) = (x.col(k).array() - shift_(k))*invScale_;
    }
    return P;
}


Eigen::MatrixXd RbfInterpolant::kernelMatrix
(
    const Points& a,
    const Points& b
) const
{
    Eigen::MatrixXd K(a.rows(), b.rows());
    kernel_.visit([&](const auto& phi)
    {
        #pragma omp parallel for schedule(static)
        for (Eigen::Index i = 0; i < a.rows(); ++i)
        {
            for (Eigen::Index j = 0; j < b.rows(); ++j)
            {
                K(i, j) = phi((a.row(i) - b.row(j)).norm());
            }
        }
    });
    return K;
}


void RbfInterpolant::checkCentres(const Points& c) const
{
    const Eigen::Index n = c.rows();
    const Eigen::Index need = polynomial_ ? dim_ + 1 : 1;
    if (n < need)
    {
        std::ostringstream os;
        os  << n << " control points are too few: at least " << need
            << " are needed" << (polynomial_ ? " to carry the polynomial" : "");
        throw Error(os.str());
    }
    if (!c.allFinite())
    {
        throw Error("control point coordinates are not finite");
    }
    if (dim_ == 2 && c.col(2).cwiseAbs().maxCoeff() > 0)
    {
        throw Error("2D interpolation needs points projected onto z = 0");
    }

    // Distinct points: nothing within a round-off distance of another
    const double extent = (c.colwise().maxCoeff() - c.colwise().minCoeff()).norm();
    const double tol = 1e-10*std::max(extent, 1e-300);
    const PointTree tree(c);
    for (Eigen::Index i = 0; i < n; ++i)
    {
        Eigen::Index other = -1;
        tree.forEachWithin(c.row(i).data(), tol, [&](std::size_t j, double)
        {
            if (Eigen::Index(j) != i) other = j;
        });
        if (other >= 0)
        {
            std::ostringstream os;
            os  << "duplicate control points " << std::min(i, other) << " and "
                << std::max(i, other) << " at (" << c.row(i) << ")";
            throw Error(os.str());
        }
    }
}


void RbfInterpolant::setCentres(const Points& centres)
{
    checkCentres(centres);
    centres_ = centres;
    alpha_.resize(0, 3);
    beta_.resize(0, 3);

    const Eigen::RowVector3d lo = centres_.colwise().minCoeff();
    const Eigen::RowVector3d hi = centres_.colwise().maxCoeff();
    shift_ = 0.5*(lo + hi);
    invScale_ = 2.0/std::max((hi - lo).norm(), 1e-300);

    const Eigen::MatrixXd P = polynomialBasis(centres_);
    if (polynomial_)
    {
        // Solvability of the polynomial part, independent of the kernel
        Eigen::JacobiSVD<Eigen::MatrixXd> svd(P);
        const auto& s = svd.singularValues();
        if (!(s(s.size() - 1) > 1e-9*s(0)))
        {
            throw Error
            (
                dim_ == 2
              ? "the control points are collinear: they cannot carry a linear"
                " polynomial in 2D"
              : "the control points are coplanar: they cannot carry a linear"
                " polynomial in 3D"
            );
        }
    }
    solver_.reset
    (
        new SaddleSolver
        (
            kernelMatrix(centres_, centres_), P, kernel_.positiveDefinite()
        )
    );
    tree_.reset(kernel_.compact() ? new PointTree(centres_) : nullptr);
}


void RbfInterpolant::solve(const Values& values)
{
    if (!solver_)
    {
        throw Error("RbfInterpolant::solve called before setCentres");
    }
    if (!values.allFinite())
    {
        throw Error("values at the control points are not finite");
    }
    solver_->solve(values, alpha_, beta_);
}


void RbfInterpolant::evaluate(const double* x, std::size_t n, double* out) const
{
    if (alpha_.rows() != centres_.rows() || centres_.rows() == 0)
    {
        throw Error("RbfInterpolant::evaluate called before solve");
    }
    const Eigen::Index nc = centres_.rows();
    const double R = kernel_.radius();
    const double* c = centres_.data();
    const double* a = alpha_.data();

    kernel_.visit([&](const auto& phi)
    {
        #pragma omp parallel for schedule(dynamic, 256)
        for (std::ptrdiff_t i = 0; i < std::ptrdiff_t(n); ++i)
        {
            const double* xi = x + 3*i;
            double s[3] = {0, 0, 0};
            auto add = [&](std::size_t j, double distSq)
            {
                const double w = phi(std::sqrt(distSq));
                s[0] += w*a[3*j];
                s[1] += w*a[3*j + 1];
                s[2] += w*a[3*j + 2];
            };
            if (phi.compact)
            {
                tree_->forEachWithin(xi, R, add);
            }
            else
            {
                for (Eigen::Index j = 0; j < nc; ++j)
                {
                    const double d0 = xi[0] - c[3*j];
                    const double d1 = xi[1] - c[3*j + 1];
                    const double d2 = xi[2] - c[3*j + 2];
                    add(j, d0*d0 + d1*d1 + d2*d2);
                }
            }
            if (polynomial_)
            {
                for (int d = 0; d < 3; ++d)
                {
                    double p = beta_(0, d);
                    for (int k = 0; k < dim_; ++k)
                    {
                        p += beta_(k + 1, d)*(xi[k] - shift_(k))*invScale_;
                    }
                    s[d] += p;
                }
            }
            out[3*i] = s[0];
            out[3*i + 1] = s[1];
            out[3*i + 2] = s[2];
        }
    });
}


Values RbfInterpolant::evaluate(const Points& x) const
{
    Values out(x.rows(), 3);
    evaluate(x.data(), x.rows(), out.data());
    return out;
}

} // namespace dcprbf
