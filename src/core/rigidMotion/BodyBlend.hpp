// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the weights s_b(x) that blend the rigid motions of
// moving bodies into the volume (BlendedRigidMotion): 1 on body b, 0 on the
// static boundary and on the other bodies.
//
// The weights are radial about each body's centre c_b (the centre of its
// rotation: give the pivot of a pitching body): with r = |x - c_b|,
// R_in the largest distance of the body's points from c_b and R_out the
// smallest distance of any static point or other body's point,
//
//     s_b = 1                                for r <= R_in
//     s_b = log(R_out / r) / log(R_out / R_in) in between
//     s_b = 0                                for r >= R_out.
//
// Why radial: the map x -> c + R(a s(x)) (x - c) has the Jacobian
// determinant 1 + a ds/dphi (phi the angle about c), so a blend that does
// not vary along circles about c never folds in the continuum, whatever the
// angle a; the whole disc r <= R_in, body and boundary layer, turns rigidly.
// The logarithm spreads the twist evenly in log r, i.e. evenly over cells
// that grow in proportion to r (the shear r s'(r) a is constant). Where
// circles around several bodies overlap, the weights are scaled to sum to 1.
// With no static point and no other body (R_out infinite) s_b = 1
// everywhere: the whole mesh moves with the body.
// R_out <= R_in (a static boundary or another body inside the body's
// circle) leaves no room for a twist: Error, naming the body.
//
// A hinged body (setHinge: a flap and the static wing it turns on, which
// share the hinge line) has static points right next to it, inside any
// ring about its centre. Its weight is the star ring's w(x) built without
// those points (the partner), times an angular factor about the hinge
// line (through c along the unit axis e):
//
//     s(x) = w(x) (1 + cos phi(x)) / 2,
//
// phi the angle about the axis between x and the body's side (the
// direction of the body's centroid from the axis). The factor is 1 on the
// body's side, 0 on the opposite one (the partner's), smooth, and
// |d/dphi| <= 1/2: the map's Jacobian about the axis, 1 + a ds/dphi, stays
// positive in the continuum up to a = 2 rad (115 deg) with w = 1, less by
// the ring's own angular slope where w falls. On the partner the factor
// is small but not 0 (its side turns by up to a few % of the angle near
// the hinge line), and on the body near the hinge less than 1: the
// interpolated rest (prescribed minus the blended rotation) takes both.
#pragma once

#include "StarEnvelope.hpp"

#include <memory>
#include <vector>

namespace dcprbf
{

class BodyBlend
{
public:

    //- boundary: the boundary points (n x 3); bodyOf: per point its body
    //  (0 .. centres.size() - 1) or -1 (static); centres: per body the
    //  centre of its rotation. Throws Error for inconsistent sizes or a body
    //  without points; weights() throws for no room between a body and the
    //  static boundary.
    BodyBlend
    (
        const Points& boundary,
        const std::vector<int>& bodyOf,
        const std::vector<Eigen::Vector3d>& centres
    );

    //- Weights at points x (x.rows() x bodies), threaded per point
    Eigen::MatrixXd weights(const Points& x) const;

    //- Replace body b's profile by the star-shaped ring (StarEnvelope with
    //  slope kappa): s = 1 - F(t), t = ln(r / R_in(u)) / ln(R_out(u) /
    //  R_in(u)) in [0, 1], u the direction from the centre; F(t) = t but
    //  for the last `ramp` of [0, 1] next to the body, where the slope
    //  falls smoothly to 0 (a C1 start of the twist). Points where R_out(u)
    //  <= R_in(u) make weights() throw Error. gridPolar > 0: the radii from
    //  a direction grid (StarEnvelope::buildGrid), for large 3D meshes
    void setStar(int body, double kappa, double ramp, int gridPolar = 0);

    //- Make body b hinged about the line through its centre along axis
    //  (non-zero): the star ring (setStar's arguments) without the points
    //  marked in partner (per boundary point; static points only), times
    //  the angular factor (1 + cos phi)/2 about the axis. Throws Error for
    //  a partner mark on a body's point, a zero axis, or a body whose
    //  centroid lies on the axis (no side)
    void setHinge
    (
        int body,
        const Eigen::Vector3d& axis,
        const std::vector<bool>& partner,
        double kappa,
        double ramp,
        int gridPolar = 0
    );

    //- Per body: the radius turning rigidly (R_in) and where the weight
    //  reaches 0 (R_out)
    double innerRadius(int body) const { return inner_[body]; }
    double outerRadius(int body) const { return outer_[body]; }

private:

    std::vector<Eigen::Vector3d> centres_;
    std::vector<double> inner_;
    std::vector<double> outer_;
    //- Per body: the star-shaped ring (null: radial) and its ramp
    std::vector<std::shared_ptr<const StarEnvelope>> stars_;
    std::vector<double> ramps_;
    //- Per body: its hinge's unit axis and side (zero: not hinged)
    std::vector<Eigen::Vector3d> hingeAxes_;
    std::vector<Eigen::Vector3d> hingeSides_;

    //- The boundary points and their bodies (for setStar)
    Points boundary_;
    std::vector<int> bodyOf_;

    //- s_b at point x
    double profile(int b, const Eigen::Vector3d& x) const;

    //- The star ring's weight of body b at x (r = |x - c_b| > 0)
    double starProfile(int b, const Eigen::Vector3d& x, double r) const;

    //- Build body b's star ring from its points and the others not
    //  skipped (skip: empty, or per boundary point)
    void buildStar(int b, double kappa, double ramp, int gridPolar,
                   const std::vector<bool>& skip);

    //- The hinge's angular factor of body b at x
    double hingeFactor(int b, const Eigen::Vector3d& x) const;

    //- Error unless R_out > R_in (radial profiles)
    void checkRadialRoom(int b) const;

    //- The star profile's F(t) (t in [0, 1])
    static double ramped(double t, double ramp);
};

} // namespace dcprbf
