// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "RigidFit.hpp"

#include <Eigen/Geometry>

#include <cmath>

namespace dcprbf
{

namespace
{

const double twoPi = 2*EIGEN_PI;

//- The angle + 2 pi k nearest to target
double nearestTurn(double angle, double target)
{
    return angle + twoPi*std::round((target - angle)/twoPi);
}

} // namespace


Eigen::Vector3d RigidMotion::displacement(const Eigen::Vector3d& x) const
{
    return rotationMatrix(rotation)*(x - centre) + centre + translation - x;
}


RigidMotion RigidMotion::about(const Eigen::Vector3d& c) const
{
    RigidMotion m(*this);
    m.centre = c;
    m.translation = centre + translation - c + rotationMatrix(rotation)*(c - centre);
    return m;
}


Eigen::Matrix3d rotationMatrix(const Eigen::Vector3d& omega)
{
    const double angle = omega.norm();
    if (angle == 0)
    {
        return Eigen::Matrix3d::Identity();
    }
    return Eigen::AngleAxisd(angle, omega/angle).toRotationMatrix();
}


RigidMotion fitRigidMotion
(
    const Points& x0,
    const Values& d,
    int dim,
    const Eigen::Vector3d& previous
)
{
    if (x0.rows() == 0 || x0.rows() != d.rows())
    {
        throw Error("fitRigidMotion: " + std::to_string(x0.rows())
            + " reference points and " + std::to_string(d.rows())
            + " displacements (need the same number, at least one)");
    }
    if (!x0.allFinite() || !d.allFinite())
    {
        throw Error("fitRigidMotion: non-finite coordinates or displacements");
    }
    if (dim != 2 && dim != 3)
    {
        throw Error("fitRigidMotion: dim must be 2 or 3");
    }

    RigidMotion m;
    m.centre = x0.colwise().mean().transpose();
    m.translation = d.colwise().mean().transpose();
    const Eigen::Matrix3Xd p0 = (x0.rowwise() - m.centre.transpose()).transpose();
    const Eigen::Matrix3Xd p =
        ((x0 + d).rowwise() - (m.centre + m.translation).transpose()).transpose();

    if (dim == 2)
    {
        // maximise sum p_i . R p0_i over rotations about z
        double c = 0, s = 0;
        for (Eigen::Index i = 0; i < p.cols(); ++i)
        {
            c += p0(0, i)*p(0, i) + p0(1, i)*p(1, i);
            s += p0(0, i)*p(1, i) - p0(1, i)*p(0, i);
        }
        const double angle = (c == 0 && s == 0) ? 0 : std::atan2(s, c);
        m.rotation = Eigen::Vector3d(0, 0, nearestTurn(angle, previous.z()));
    }
    else
    {
        const Eigen::Matrix4d T = Eigen::umeyama(p0, p, false);
        const Eigen::AngleAxisd aa(Eigen::Matrix3d(T.topLeftCorner<3, 3>()));
        Eigen::Vector3d axis = aa.axis();
        double angle = aa.angle();
        if (angle < 1e-14 && previous.norm() > 0)
        {
            // the identity is a whole number of turns about any axis
            axis = previous.normalized();
            angle = 0;
        }
        m.rotation = nearestTurn(angle, previous.dot(axis))*axis;
    }

    const Eigen::Matrix3d R = rotationMatrix(m.rotation);
    m.rmsResidual = std::sqrt((R*p0 - p).colwise().squaredNorm().mean());
    return m;
}

} // namespace dcprbf
