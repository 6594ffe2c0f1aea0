// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the rigid motions of several bodies blended into
// the volume by per-point weights.
//
// Body b moves rigidly by (c_b, omega_b, t_b) (RigidMotion). A point x with
// weights s_b(x) >= 0 (1 on body b, 0 on the other bodies and the static
// boundary, sum <= 1 in between) moves by the blended rigid motion
//
//     omega(x) = sum_b s_b omega_b             (rotation vectors, log space)
//     c(x)     = sum_b s_b c_b / sum_b s_b     (the bodies' centres)
//     t(x)     = sum_b s_b t_b
//     x'       = c(x) + R(omega(x)) (x - c(x)) + t(x)
//
// For one body this is the rotation by s(x) times the body's angle about its
// centre plus s(x) times its translation (Bos, van Oudheusden & Bijl 2013,
// quaternion interpolation from the identity). On body b the motion is body
// b's exactly; where the weights sum to 1 and every body moves by the same
// rigid motion, x' is that motion exactly whatever the weights (c and t
// enter linearly for a common R); where every weight is 0 nothing moves.
//
// dcpRBFRotation passes the rotations only (zero translations): a body's
// translation is interpolated with the non-rigid rest, so that pure
// translation behaves as displacement interpolation.
#pragma once

#include "RigidFit.hpp"

#include <vector>

namespace dcprbf
{

//- Displacement of the points x (n x 3) under the bodies' motions blended
//  by weights (n x bodies.size()); out is resized to n x 3. Threaded per
//  point (the same result on any number of threads).
void blendedRigidDisplacement
(
    const std::vector<RigidMotion>& bodies,
    const Points& x,
    const Eigen::MatrixXd& weights,
    Values& out
);

} // namespace dcprbf
