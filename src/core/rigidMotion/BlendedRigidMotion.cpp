// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "BlendedRigidMotion.hpp"

namespace dcprbf
{

void blendedRigidDisplacement
(
    const std::vector<RigidMotion>& bodies,
    const Points& x,
    const Eigen::MatrixXd& weights,
    Values& out
)
{
    const Eigen::Index n = x.rows();
    const Eigen::Index nb = Eigen::Index(bodies.size());
    if (weights.rows() != n || weights.cols() != nb)
    {
        throw Error("blendedRigidDisplacement: weights are "
            + std::to_string(weights.rows()) + " x "
            + std::to_string(weights.cols()) + ", expected "
            + std::to_string(n) + " x " + std::to_string(nb));
    }
    out.setZero(n, 3);

    #pragma omp parallel for schedule(static)
    for (Eigen::Index i = 0; i < n; ++i)
    {
        double w = 0;
        Eigen::Vector3d omega(Eigen::Vector3d::Zero());
        Eigen::Vector3d c(Eigen::Vector3d::Zero());
        Eigen::Vector3d t(Eigen::Vector3d::Zero());
        for (Eigen::Index b = 0; b < nb; ++b)
        {
            const double s = weights(i, b);
            w += s;
            omega += s*bodies[b].rotation;
            c += s*bodies[b].centre;
            t += s*bodies[b].translation;
        }
        if (w <= 0)
        {
            continue;
        }
        c /= w;
        const Eigen::Vector3d xi(x.row(i).transpose());
        out.row(i) = (rotationMatrix(omega)*(xi - c) + c + t - xi).transpose();
    }
}

} // namespace dcprbf
