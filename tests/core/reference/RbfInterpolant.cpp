// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "RbfInterpolant.hpp"
#include "PointSetChecks.hpp"

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
    frame_(polynomial, dim == 2 ? 2 : 3),
    evaluator_(kernel, frame_)
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
    return frame_.basis(x);
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


void RbfInterpolant::setCentres(const Points& centres)
{
    PointSetChecks::checkCoordinates(centres, dim_, "control point");
    PointSetChecks::checkControlSet
    (
        centres, LinearPolynomial::boundingBox(polynomial_, dim_, centres)
    );
    centres_ = centres;
    alpha_.resize(0, 3);
    beta_.resize(0, 3);
    evaluator_ = RbfEvaluator(kernel_, frame_);  // drop old coefficients
    solver_.reset();

    frame_ = LinearPolynomial::boundingBox(polynomial_, dim_, centres_);
    solver_.reset
    (
        new SaddleSolver
        (
            kernelMatrix(centres_, centres_),
            frame_.basis(centres_),
            kernel_.positiveDefinite()
        )
    );
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
    evaluator_ = RbfEvaluator(kernel_, frame_);
    evaluator_.assign(centres_, alpha_, beta_);
}


void RbfInterpolant::evaluate(const double* x, std::size_t n, double* out) const
{
    if (alpha_.rows() != centres_.rows() || centres_.rows() == 0)
    {
        throw Error("RbfInterpolant::evaluate called before solve");
    }
    evaluator_.evaluate(x, n, out);
}


Values RbfInterpolant::evaluate(const Points& x) const
{
    Values out(x.rows(), 3);
    evaluate(x.data(), x.rows(), out.data());
    return out;
}

} // namespace dcprbf
