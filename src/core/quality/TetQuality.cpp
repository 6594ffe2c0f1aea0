// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "TetQuality.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace dcprbf
{

double TetQuality::compute
(
    const Eigen::Matrix3d& E0,
    const Eigen::Matrix3d& E,
    Metric metric
)
{
    const double det0 = E0.determinant();
    const double scale = E0.colwise().norm().maxCoeff();
    if (!(std::abs(det0) > 1e-14*scale*scale*scale))
    {
        return 1.0;
    }
    const Eigen::Matrix3d A = E*E0.inverse();
    const double J = E.determinant()/det0;
    if (!(J > 0))
    {
        return J;
    }
    const double fSize = std::min(J, 1.0/J);
    const double fShape = 3.0*std::cbrt(J*J)/A.squaredNorm();
    switch (metric)
    {
        case Metric::size: return fSize;
        case Metric::shape: return fShape;
        default: return std::sqrt(fSize)*fShape;
    }
}


double TetQuality::compute
(
    const Eigen::Vector3d ref[4],
    const Eigen::Vector3d cur[4],
    Metric metric
)
{
    Eigen::Matrix3d E0, E;
    for (int k = 0; k < 3; ++k)
    {
        E0.col(k) = ref[k + 1] - ref[0];
        E.col(k) = cur[k + 1] - cur[0];
    }
    return compute(E0, E, metric);
}

} // namespace dcprbf
