// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the linear polynomial part of an RBF interpolant
// and the coordinate frame it is written in.
//
//     p(x) = beta_0 + sum_{k < dim} beta_{k+1} (x_k - shift_k) * invScale
//
// i.e. the basis is q(x) = (1, (x_0 - s_0)/h, ..., (x_{dim-1} - s_{dim-1})/h)
// with h = 1/invScale. Taking the shift at the centre of a bounding box and
// h = half its diagonal keeps every basis value in [-1, 1] inside the box,
// which keeps the saddle system well scaled. A disabled polynomial has an
// empty basis (size() == 0).
//
// The frame matters for the coefficients beta only, not for the function
// p(x): changeFrame() re-expresses beta in another frame.
#pragma once

#include "Types.hpp"

namespace dcprbf
{

class LinearPolynomial
{
public:
    //- Explicit frame; throws Error for dim not 2 or 3, invScale <= 0
    LinearPolynomial
    (
        bool enabled,
        int dim,
        const Eigen::RowVector3d& shift = Eigen::RowVector3d::Zero(),
        double invScale = 1.0
    );

    //- Frame of the bounding box of the rows of x: shift = box centre,
    //  invScale = 2/diagonal (1 for a single point)
    static LinearPolynomial boundingBox(bool enabled, int dim, const Points& x);

    bool enabled() const { return enabled_; }
    int dim() const { return dim_; }

    //- Number of basis functions: dim + 1, or 0 when disabled
    int size() const { return enabled_ ? dim_ + 1 : 0; }

    const Eigen::RowVector3d& shift() const { return shift_; }
    double invScale() const { return invScale_; }

    //- Diagonal of the frame's box (2/invScale)
    double diameter() const { return 2.0/invScale_; }

    //- Basis values q(x) at one point x (xyz) into out[0 .. size())
    void basis(const double* x, double* out) const
    {
        if (!enabled_) return;
        out[0] = 1.0;
        for (int k = 0; k < dim_; ++k)
        {
            out[k + 1] = (x[k] - shift_(k))*invScale_;
        }
    }

    //- Basis at the rows of x: x.rows() x size()
    Eigen::MatrixXd basis(const Points& x) const;

    //- p(x) for one point: out[d] = sum_i q_i(x) beta(i, d), d < 3
    void value(const double* x, const Eigen::MatrixX3d& beta, double* out) const;

    //- Throw Error unless the basis has full column rank on the rows of x
    //  (smallest singular value > 1e-9 x largest): "collinear" in 2D,
    //  "coplanar" in 3D, "too few" below dim + 1 points. No-op when disabled.
    void checkUnisolvent(const Points& x) const;

    //- The same polynomial p written in frame `to`: returns beta' with
    //  sum_i q'_i(x) beta'(i, d) = sum_i q_i(x) beta(i, d) for every x
    Eigen::MatrixX3d changeFrame
    (
        const Eigen::MatrixX3d& beta,
        const LinearPolynomial& to
    ) const;

private:
    bool enabled_;
    int dim_;
    Eigen::RowVector3d shift_;
    double invScale_;
};

} // namespace dcprbf
