// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the best-fit rigid motion of a set of points
// (least squares: Kabsch/Umeyama in 3D, the closed form in 2D) and
// rotation vectors.
//
// A rigid motion is kept as (centre c, rotation vector omega, translation t):
//     x -> c + R(omega) (x - c) + t
// with c the centroid of the reference points and R(omega) the rotation by
// |omega| about omega/|omega| (Rodrigues). The rotation matrix of a fit only
// knows the angle modulo 2 pi; fitRigidMotion returns the equivalent rotation
// vector (same axis, angle + 2 pi k) nearest the previous step's, so a body
// that keeps turning has an angle that grows continuously past 180 degrees.
#pragma once

#include "Types.hpp"

#include <Eigen/Core>

namespace dcprbf
{

struct RigidMotion
{
    //- Centroid of the reference points
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    //- Rotation vector (axis times angle in radians), continuous in time
    Eigen::Vector3d rotation = Eigen::Vector3d::Zero();
    //- Displacement of the centre
    Eigen::Vector3d translation = Eigen::Vector3d::Zero();
    //- Root-mean-square distance between the fitted and the given positions
    double rmsResidual = 0;

    //- Displacement of reference point x under this motion
    Eigen::Vector3d displacement(const Eigen::Vector3d& x) const;

    //- The same motion written about another centre (translation adjusted)
    RigidMotion about(const Eigen::Vector3d& c) const;
};

//- Rotation matrix of rotation vector omega (Rodrigues)
Eigen::Matrix3d rotationMatrix(const Eigen::Vector3d& omega);

//- Best-fit rigid motion taking the reference points x0 (n x 3) to x0 + d.
//  dim 2: rotation about the z axis only (the points' z is ignored in the
//  rotation). previous: the last fit's rotation vector (zero at the start).
//  Throws Error for no points, sizes that differ or non-finite input.
RigidMotion fitRigidMotion
(
    const Points& x0,
    const Values& d,
    int dim,
    const Eigen::Vector3d& previous = Eigen::Vector3d::Zero()
);

} // namespace dcprbf
