// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "CellQualityBound.hpp"

#include <algorithm>
#include <cmath>

namespace dcprbf
{

namespace
{

const double infinity = std::numeric_limits<double>::infinity();

//- The mean of the nv vertices' coordinates into m, and the largest
//  absolute coordinate into big
inline void mean(const double* x, const int* v, const int nv, double m[3], double& big)
{
    m[0] = m[1] = m[2] = 0;
    big = 0;
    for (int k = 0; k < nv; ++k)
    {
        const double* y = x + 3*std::size_t(v[k]);
        for (int d = 0; d < 3; ++d)
        {
            m[d] += y[d];
            big = std::max(big, std::abs(y[d]));
        }
    }
    for (int d = 0; d < 3; ++d) m[d] /= nv;
}

//- A lower bound of the least singular value squared of the 3 x 3 matrix
//  M, given by the coefficients of the characteristic polynomial of M^T M,
//  p(l) = l^3 - c1 l^2 + c2 l - c3: c1 = |M|_F^2, c2 = |adj M|_F^2 (the
//  squared 2 x 2 minors), c3 = det(M)^2, each computed from M itself (not
//  from M^T M, whose forming loses digits as cond(M)^2). Newton steps from
//  c3/c2 (<= the least eigenvalue l1, as c2 >= l2 l3): p is increasing and
//  concave up to l1 (l1 <= c1/3), so each step stays below l1; within a
//  relative 1e-12 of it after n steps (and u cond(M) from det(M))
inline double leastSquaredSingularValueBelow
(
    const double c1,
    const double c2,
    const double c3,
    const int n
)
{
    if (!(c3 > 0) || !(c2 > 0))
    {
        return 0;
    }
    double l = c3/c2;
    for (int i = 0; i < n; ++i)
    {
        const double p = ((l - c1)*l + c2)*l - c3;
        const double dp = (3*l - 2*c1)*l + c2;
        if (!(p < 0) || !(dp > 0))
        {
            break;
        }
        l -= p/dp;
    }
    // the last step's round-off
    return std::max(0.0, l*(1 - 1e-12));
}


//- T = S M^-1, S = sum (x - m)(X - m0)^T over the nv vertices (minv: M^-1's
//  upper triangle by rows)
inline void fitMap
(
    const double* x0,
    const double* x,
    const int* v,
    const int nv,
    const double m0[3],
    const double m[3],
    const double minv[6],
    double T[3][3]
)
{
    double S[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    for (int k = 0; k < nv; ++k)
    {
        const double* y0 = x0 + 3*std::size_t(v[k]);
        const double* y = x + 3*std::size_t(v[k]);
        const double X[3] = {y0[0] - m0[0], y0[1] - m0[1], y0[2] - m0[2]};
        for (int i = 0; i < 3; ++i)
        {
            const double u = y[i] - m[i];
            for (int j = 0; j < 3; ++j) S[i][j] += u*X[j];
        }
    }
    const double Mi[3][3] =
    {
        {minv[0], minv[1], minv[2]},
        {minv[1], minv[3], minv[4]},
        {minv[2], minv[4], minv[5]}
    };
    for (int i = 0; i < 3; ++i)
    {
        for (int j = 0; j < 3; ++j)
        {
            T[i][j] = S[i][0]*Mi[0][j] + S[i][1]*Mi[1][j] + S[i][2]*Mi[2][j];
        }
    }
}


//- The largest squared residual of x - m against T (X - m0) over the nv
//  vertices into r2, the largest |X - m0|^2 into l2
inline void largestResidual
(
    const double* x0,
    const double* x,
    const int* v,
    const int nv,
    const double m0[3],
    const double m[3],
    const double T[3][3],
    double& r2,
    double& l2
)
{
    r2 = 0;
    l2 = 0;
    for (int k = 0; k < nv; ++k)
    {
        const double* y0 = x0 + 3*std::size_t(v[k]);
        const double* y = x + 3*std::size_t(v[k]);
        const double X[3] = {y0[0] - m0[0], y0[1] - m0[1], y0[2] - m0[2]};
        double e2 = 0;
        for (int i = 0; i < 3; ++i)
        {
            const double e = (y[i] - m[i]) - (T[i][0]*X[0] + T[i][1]*X[1] + T[i][2]*X[2]);
            e2 += e*e;
        }
        r2 = std::max(r2, e2);
        l2 = std::max(l2, X[0]*X[0] + X[1]*X[1] + X[2]*X[2]);
    }
}


//- |adj T|_F^2: the sum of T's 2 x 2 minors squared
inline double adjugateSquared(const double T[3][3])
{
    double adj2 = 0;
    for (int i = 0; i < 3; ++i)
    {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        for (int j = 0; j < 3; ++j)
        {
            const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            const double minor = T[i1][j1]*T[i2][j2] - T[i1][j2]*T[i2][j1];
            adj2 += minor*minor;
        }
    }
    return adj2;
}

} // namespace


double CellQualityBound::inverseNorm(const double* e0, const double* e1, const double* e2)
{
    const auto dot = [](const double* a, const double* b)
    {
        return a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
    };
    const double c[3] =
    {
        e1[1]*e2[2] - e1[2]*e2[1], e1[2]*e2[0] - e1[0]*e2[2], e1[0]*e2[1] - e1[1]*e2[0]
    };
    const double det0 = dot(e0, c);
    const double scale2 = std::max({dot(e0, e0), dot(e1, e1), dot(e2, e2)});
    if (!(det0*det0 > 1e-28*scale2*scale2*scale2))
    {
        return infinity;
    }
    // |E^-1|_2 = 1/(the least singular value of E), from E's own
    // coefficients; at most |E^-1|_F = |adj E|_F/|det E| (rigorous, up to
    // sqrt(3) loose: the bound for a badly conditioned E). Raised by the
    // round-off of det E (u cond(E), cond(E) <= |E|_F |E^-1|_F)
    const double a1[3] =
    {
        e2[1]*e0[2] - e2[2]*e0[1], e2[2]*e0[0] - e2[0]*e0[2], e2[0]*e0[1] - e2[1]*e0[0]
    };
    const double a2[3] =
    {
        e0[1]*e1[2] - e0[2]*e1[1], e0[2]*e1[0] - e0[0]*e1[2], e0[0]*e1[1] - e0[1]*e1[0]
    };
    const double adj2 = dot(c, c) + dot(a1, a1) + dot(a2, a2);
    const double E2 = dot(e0, e0) + dot(e1, e1) + dot(e2, e2);
    const double frobenius = std::sqrt(adj2)/std::abs(det0);
    const double margin = 1 + 1e-13*std::sqrt(E2)*frobenius;
    const double l = leastSquaredSingularValueBelow(E2, adj2, det0*det0, 100);
    return margin*(l > 0 ? std::min(frobenius, 1/std::sqrt(l)) : frobenius);
}


CellQualityBound::CellQualityBound
(
    const double* x0,
    const int* v,
    const int nv,
    const double kappa
)
{
    double m[3], big;
    mean(x0, v, nv, m, big);
    double M[6] = {0, 0, 0, 0, 0, 0};
    for (int k = 0; k < nv; ++k)
    {
        const double* y = x0 + 3*std::size_t(v[k]);
        const double a = y[0] - m[0], b = y[1] - m[1], c = y[2] - m[2];
        M[0] += a*a; M[1] += a*b; M[2] += a*c;
        M[3] += b*b; M[4] += b*c; M[5] += c*c;
    }
    // the inverse by cofactors; a (nearly) flat cell is not bounded
    const double c00 = M[3]*M[5] - M[4]*M[4];
    const double c01 = M[2]*M[4] - M[1]*M[5];
    const double c02 = M[1]*M[4] - M[2]*M[3];
    const double det = M[0]*c00 + M[1]*c01 + M[2]*c02;
    const double tr = M[0] + M[3] + M[5];
    if (!(det > 1e-12*tr*tr*tr) || !(kappa < infinity))
    {
        return;
    }
    minv_[0] = c00/det;
    minv_[1] = c01/det;
    minv_[2] = c02/det;
    minv_[3] = (M[0]*M[5] - M[2]*M[2])/det;
    minv_[4] = (M[1]*M[2] - M[0]*M[4])/det;
    minv_[5] = (M[0]*M[3] - M[1]*M[1])/det;
    kappa_ = kappa;
}


double CellQualityBound::fromMap
(
    const double J,
    const double F2,
    const double s,
    const double eps,
    const TetQuality::Metric metric
)
{
    if (!(J > 0) || !(F2 > 0) || !(s > 0))
    {
        return -infinity;
    }
    if (!(eps < s))
    {
        return -infinity;
    }
    const double rho = eps/s;
    const double Jlo = J*(1 - rho)*(1 - rho)*(1 - rho);
    const double Jhi = J*(1 + rho)*(1 + rho)*(1 + rho);
    const double F = std::sqrt(F2) + std::sqrt(3.0)*eps;
    const double fSize = std::min(Jlo, 1/Jhi);
    const double fShape = 3*std::cbrt(Jlo*Jlo)/(F*F);
    double q;
    switch (metric)
    {
        case TetQuality::Metric::size: q = fSize; break;
        case TetQuality::Metric::shape: q = fShape; break;
        default: q = std::sqrt(fSize)*fShape;
    }
    // round-off of the computed values: a relative 1e-12 below
    return q - 1e-12*std::abs(q);
}


double CellQualityBound::lower
(
    const double* x0,
    const double* x,
    const int* v,
    const int nv,
    const TetQuality::Metric metric
) const
{
    if (!bounded())
    {
        return -infinity;
    }
    double m0[3], m[3], big0, big;
    mean(x0, v, nv, m0, big0);
    mean(x, v, nv, m, big);

    // the map T fitted, x - m ~ T (X - m0)
    double T[3][3];
    fitMap(x0, x, v, nv, m0, m, minv_, T);

    // the largest residual, raised by the coordinates' round-off
    double r2, l2;
    largestResidual(x0, x, v, nv, m0, m, T, r2, l2);
    const double F2 =
        T[0][0]*T[0][0] + T[0][1]*T[0][1] + T[0][2]*T[0][2]
      + T[1][0]*T[1][0] + T[1][1]*T[1][1] + T[1][2]*T[1][2]
      + T[2][0]*T[2][0] + T[2][1]*T[2][1] + T[2][2]*T[2][2];
    const double r =
        std::sqrt(r2) + 1e-13*(big + std::sqrt(F2)*(big0 + std::sqrt(l2)));
    const double J =
        T[0][0]*(T[1][1]*T[2][2] - T[1][2]*T[2][1])
      - T[0][1]*(T[1][0]*T[2][2] - T[1][2]*T[2][0])
      + T[0][2]*(T[1][0]*T[2][1] - T[1][1]*T[2][0]);
    // the least singular value of T from below (its 2 x 2 minors squared:
    // |adj T|_F^2), lowered by det T's round-off (u cond(T), cond(T) <=
    // |T|_F^2 / s)
    const double adj2 = adjugateSquared(T);
    double s = std::sqrt(leastSquaredSingularValueBelow(F2, adj2, J*J, 4));
    s *= std::max(0.0, 1 - 1e-13*F2/std::max(s*s, 1e-300));
    return fromMap(J, F2, s, 2*std::sqrt(3.0)*r*kappa_, metric);
}

} // namespace dcprbf
