// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "LinearPolynomial.hpp"

#include <Eigen/SVD>

#include <cmath>
#include <sstream>

namespace dcprbf
{

LinearPolynomial::LinearPolynomial
(
    bool enabled,
    int dim,
    const Eigen::RowVector3d& shift,
    double invScale
)
:
    enabled_(enabled),
    dim_(dim),
    shift_(shift),
    invScale_(invScale)
{
    if (dim != 2 && dim != 3)
    {
        throw Error("dimension must be 2 or 3, got " + std::to_string(dim));
    }
    if (!(invScale > 0) || !std::isfinite(invScale) || !shift.allFinite())
    {
        std::ostringstream os;
        os  << "polynomial frame needs a finite shift and a positive finite"
            << " inverse scale, got " << invScale;
        throw Error(os.str());
    }
}


LinearPolynomial LinearPolynomial::boundingBox
(
    bool enabled,
    int dim,
    const Points& x
)
{
    if (x.rows() == 0)
    {
        return LinearPolynomial(enabled, dim);
    }
    if (!x.allFinite())
    {
        throw Error("point coordinates are not finite");
    }
    const Eigen::RowVector3d lo = x.colwise().minCoeff();
    const Eigen::RowVector3d hi = x.colwise().maxCoeff();
    const double diagonal = (hi - lo).norm();
    return LinearPolynomial
    (
        enabled, dim, 0.5*(lo + hi), diagonal > 0 ? 2.0/diagonal : 1.0
    );
}


Eigen::MatrixXd LinearPolynomial::basis(const Points& x) const
{
    Eigen::MatrixXd Q(x.rows(), size());
    if (!enabled_) return Q;
    Q.col(0).setOnes();
    for (int k = 0; k < dim_; ++k)
    {
        Q.col(k + 1) = (x.col(k).array() - shift_(k))*invScale_;
    }
    return Q;
}


void LinearPolynomial::value
(
    const double* x,
    const Eigen::MatrixX3d& beta,
    double* out
) const
{
    out[0] = out[1] = out[2] = 0;
    if (!enabled_) return;
    double q[4];
    basis(x, q);
    for (int i = 0; i < size(); ++i)
    {
        out[0] += q[i]*beta(i, 0);
        out[1] += q[i]*beta(i, 1);
        out[2] += q[i]*beta(i, 2);
    }
}


void LinearPolynomial::checkUnisolvent(const Points& x) const
{
    if (!enabled_) return;
    if (x.rows() < size())
    {
        std::ostringstream os;
        os  << x.rows() << " points are too few to carry the linear"
            << " polynomial: at least " << size() << " are needed";
        throw Error(os.str());
    }
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(basis(x));
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


Eigen::MatrixX3d LinearPolynomial::changeFrame
(
    const Eigen::MatrixX3d& beta,
    const LinearPolynomial& to
) const
{
    if (to.enabled_ != enabled_ || to.dim_ != dim_ || beta.rows() != size())
    {
        throw Error("polynomial frames differ in size: cannot convert");
    }
    if (!enabled_) return beta;
    // (x_k - s_k) a = (x_k - t_k) b (a/b) + (t_k - s_k) a  with a, b the
    // inverse scales of this frame and of `to`
    Eigen::MatrixX3d out(beta.rows(), 3);
    out.row(0) = beta.row(0);
    for (int k = 0; k < dim_; ++k)
    {
        out.row(k + 1) = beta.row(k + 1)*(invScale_/to.invScale_);
        out.row(0) += beta.row(k + 1)*((to.shift_(k) - shift_(k))*invScale_);
    }
    return out;
}

} // namespace dcprbf
