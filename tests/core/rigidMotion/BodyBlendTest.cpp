// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the radial blend weights of moving bodies.
#include "BlendedRigidMotion.hpp"
#include "BodyBlend.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace dcprbf;

namespace
{

//- n points on the circle of radius r about c (z = 0)
Points ring(int n, double r, const Eigen::Vector3d& c = Eigen::Vector3d::Zero())
{
    Points p(n, 3);
    for (int i = 0; i < n; ++i)
    {
        const double a = 2*EIGEN_PI*i/n;
        p.row(i) << c.x() + r*std::cos(a), c.y() + r*std::sin(a), 0;
    }
    return p;
}

//- Body: an ellipse of semi-axes (0.5, 0.1) about the origin; walls: the
//  square |x|, |y| = 2
struct Channel
{
    Points boundary;
    std::vector<int> bodyOf;
    Channel()
    {
        const int nb = 40, nw = 80;
        boundary.resize(nb + nw, 3);
        for (int i = 0; i < nb; ++i)
        {
            const double a = 2*EIGEN_PI*i/nb;
            boundary.row(i) << 0.5*std::cos(a), 0.1*std::sin(a), 0;
            bodyOf.push_back(0);
        }
        for (int i = 0; i < nw; ++i)
        {
            const double t = -2 + 4.0*(i/4)/(nw/4);
            const int side = i % 4;
            boundary.row(nb + i) << (side == 0 ? 2 : side == 1 ? -2 : t),
                                    (side == 2 ? 2 : side == 3 ? -2 : t), 0;
            bodyOf.push_back(-1);
        }
    }
};

} // namespace


TEST(BodyBlend, OneOnTheBodyZeroOnTheWallsRadialInBetween)
{
    const Channel ch;
    const BodyBlend blend(ch.boundary, ch.bodyOf, {Eigen::Vector3d::Zero()});
    EXPECT_NEAR(blend.innerRadius(0), 0.5, 1e-14);
    EXPECT_NEAR(blend.outerRadius(0), 2, 1e-14);
    const Eigen::MatrixXd w = blend.weights(ch.boundary);
    for (Eigen::Index i = 0; i < ch.boundary.rows(); ++i)
    {
        EXPECT_EQ(w(i, 0), ch.bodyOf[i] == 0 ? 1.0 : 0.0) << i;
    }
    // constant on circles, log-linear in r
    const Eigen::MatrixXd c = blend.weights(ring(16, 1.0));
    EXPECT_LT((c.array() - std::log(2.0)/std::log(4.0)).abs().maxCoeff(), 1e-14);
}


TEST(BodyBlend, RingTurnsByTheBlendedAngleAndStaysARing)
{
    // a rigid turn of 150 deg: a ring of points between body and walls turns
    // by s(r) times 150 deg and keeps its radius (no point leaves its circle)
    const Channel ch;
    const BodyBlend blend(ch.boundary, ch.bodyOf, {Eigen::Vector3d::Zero()});
    RigidMotion m;
    m.rotation = {0, 0, 150*EIGEN_PI/180};
    const Points x = ring(36, 1.2);
    Values d;
    blendedRigidDisplacement({m}, x, blend.weights(x), d);
    const double s = std::log(2/1.2)/std::log(4.0);
    for (Eigen::Index i = 0; i < x.rows(); ++i)
    {
        const Eigen::Vector3d p = x.row(i).transpose(), q = p + d.row(i).transpose();
        EXPECT_NEAR(q.norm(), 1.2, 1e-13);
        EXPECT_NEAR(std::atan2(p.x()*q.y() - p.y()*q.x(), p.dot(q)), s*150*EIGEN_PI/180, 1e-13);
    }
}


TEST(BodyBlend, OverlappingBodiesSumToAtMostOne)
{
    Points b(4, 3);
    b << -1, 0, 0,   -0.6, 0, 0,   0.6, 0, 0,   1, 0, 0;
    Points walls = ring(40, 5);
    Points all(44, 3);
    all << b, walls;
    std::vector<int> bodyOf{0, 0, 1, 1};
    bodyOf.resize(44, -1);
    const BodyBlend blend(all, bodyOf, {Eigen::Vector3d(-0.8, 0, 0), Eigen::Vector3d(0.8, 0, 0)});
    const Eigen::MatrixXd w = blend.weights(ring(50, 0.5, Eigen::Vector3d(0, 0.2, 0)));
    EXPECT_LE(w.rowwise().sum().maxCoeff(), 1 + 1e-14);
    EXPECT_GT(w.minCoeff(), -1e-300);
    const Eigen::MatrixXd onBodies = blend.weights(b);
    EXPECT_EQ(onBodies(0, 0), 1); EXPECT_EQ(onBodies(0, 1), 0);
    EXPECT_EQ(onBodies(3, 1), 1); EXPECT_EQ(onBodies(3, 0), 0);
}


TEST(BodyBlend, RefusesAWallInsideTheBodysCircle)
{
    Channel ch;
    ch.boundary.row(ch.boundary.rows() - 1) << 0.3, 0.3, 0;   // wall point at r 0.42 < 0.5
    const BodyBlend tight(ch.boundary, ch.bodyOf, {Eigen::Vector3d::Zero()});
    EXPECT_THROW(tight.weights(ch.boundary), Error);
    EXPECT_THROW(BodyBlend(ch.boundary, std::vector<int>(3, 0), {Eigen::Vector3d::Zero()}), Error);
    std::vector<int> noBody(ch.bodyOf.size(), -1);
    EXPECT_THROW(BodyBlend(ch.boundary, noBody, {Eigen::Vector3d::Zero()}), Error);
}


TEST(BodyBlend, NothingStaticMovesEverythingWithTheBody)
{
    const Points body = ring(12, 0.5);
    const BodyBlend blend(body, std::vector<int>(12, 0), {Eigen::Vector3d(0.1, 0, 0)});
    EXPECT_EQ(blend.weights(ring(30, 7.0)).minCoeff(), 1.0);
}


TEST(BodyBlend, StarRingFollowsAThinBodyAndFarWalls)
{
    // the ellipse (0.5 x 0.1) in the square |x|, |y| = 2: with kappa 0 the
    // star ring is the radial one; with kappa > 0 the twist starts closer to
    // the body across its thin side, and s is 1 on the body, 0 on the walls
    const Channel ch;
    BodyBlend radial(ch.boundary, ch.bodyOf, {Eigen::Vector3d::Zero()});
    BodyBlend star0(ch.boundary, ch.bodyOf, {Eigen::Vector3d::Zero()});
    star0.setStar(0, 0.0, 0.0);
    const Points probe = ring(72, 1.3);
    EXPECT_LT((radial.weights(probe) - star0.weights(probe)).cwiseAbs().maxCoeff(), 1e-14);

    BodyBlend star(ch.boundary, ch.bodyOf, {Eigen::Vector3d::Zero()});
    star.setStar(0, 0.25, 0.1);
    const Eigen::MatrixXd w = star.weights(ch.boundary);
    for (Eigen::Index i = 0; i < ch.boundary.rows(); ++i)
    {
        EXPECT_EQ(w(i, 0), ch.bodyOf[i] == 0 ? 1.0 : 0.0) << i;
    }
    Points above(1, 3);
    above << 0, 0.4, 0;     // inside the radial ring's rigid disc (r < 0.5)
    EXPECT_EQ(radial.weights(above)(0, 0), 1.0);
    EXPECT_LT(star.weights(above)(0, 0), 1.0);
}


TEST(BodyBlend, StarAngularSlopeIsBounded)
{
    // |ds/dphi| <= kappa / ln(R_out/R_in) <= kappa / ln(R_out,min/R_in,max)
    // on a circle between body and walls (finite differences, no ramp)
    const Channel ch;
    BodyBlend star(ch.boundary, ch.bodyOf, {Eigen::Vector3d::Zero()});
    const double kappa = 0.25;
    star.setStar(0, kappa, 0.0);
    const int n = 3600;
    const Eigen::MatrixXd w = star.weights(ring(n, 1.0));
    double slope = 0;
    for (int i = 0; i < n; ++i)
    {
        slope = std::max(slope, std::abs(w((i + 1) % n, 0) - w(i, 0))/(2*double(EIGEN_PI)/n));
    }
    EXPECT_GT(slope, 0);
    EXPECT_LE(slope, kappa/std::log(2/0.5)*1.001);
}


TEST(StarEnvelope, GridBoundsNeverWidenTheRing)
{
    // a thin 3D body (a flat ellipse in z = 0) in a box: the grid's radii
    // bound the exact ones from the safe side and stay within
    // 2 kappa x spacing of them
    Points body(200, 3), box(600, 3);
    for (int i = 0; i < 200; ++i)
    {
        const double a = 2*double(EIGEN_PI)*i/200;
        body.row(i) << 0.8*std::cos(a), 0.3*std::sin(a), 0.02*std::sin(3*a);
    }
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(-2, 2);
    for (int i = 0; i < 600; ++i)
    {
        Eigen::Vector3d p(u(gen), u(gen), u(gen));
        p(i % 3) = (i % 2 ? 2.0 : -2.5);     // on a face of the box
        box.row(i) = p.transpose();
    }
    const double kappa = 0.25;
    StarEnvelope exact(Eigen::Vector3d::Zero(), body, box, kappa);
    StarEnvelope grid(Eigen::Vector3d::Zero(), body, box, kappa);
    const int nPolar = 45;
    grid.buildGrid(nPolar);
    const double tol = 2*kappa*double(EIGEN_PI)/nPolar*1.5;
    for (int k = 0; k < 2000; ++k)
    {
        const Eigen::Vector3d x(u(gen), u(gen), u(gen));
        double ei, eo, gi, go;
        exact.exactRadii(x.normalized(), ei, eo);
        grid.radii(x, gi, go);
        ASSERT_GE(gi, ei - 1e-12) << k;
        ASSERT_LE(go, eo + 1e-12) << k;
        EXPECT_LT(gi - ei, tol) << k;
        EXPECT_LT(eo - go, tol) << k;
    }
}


namespace
{

//- A flap hinged at the origin in the plane (x, y), the hinge axis z: the
//  flap's plate along +x (0.05 .. 1, y = +-0.02: the body), the wing's
//  along -x (-1 .. -0.05: static, the partner), and far walls: the circle
//  of radius 5 (static)
struct Hinge
{
    Points boundary;
    std::vector<int> bodyOf;
    std::vector<bool> partner;
    Hinge()
    {
        const int n = 20, nw = 120;
        boundary.resize(4*n + nw, 3);
        for (int i = 0; i < n; ++i)
        {
            const double x = 0.05 + 0.95*i/(n - 1);
            for (int side = 0; side < 2; ++side)
            {
                boundary.row(2*i + side) << x, side ? 0.02 : -0.02, 0;
                boundary.row(2*n + 2*i + side) << -x, side ? 0.02 : -0.02, 0;
            }
        }
        bodyOf.assign(2*n, 0);
        bodyOf.resize(4*n, -1);
        partner.assign(4*n, false);
        for (int i = 2*n; i < 4*n; ++i) partner[i] = true;
        boundary.bottomRows(nw) = ring(nw, 5);
        bodyOf.resize(4*n + nw, -1);
        partner.resize(4*n + nw, false);
    }
};

} // namespace


TEST(BodyBlend, HingeTurnsTheFlapSideKeepsThePartnersSide)
{
    // the wing touches the flap's ring: a plain ring has no room; hinged,
    // the weight is 1 at the flap's trailing edge (straight along its
    // side), 0 at the wing's leading edge (straight opposite) and at the
    // walls, 1/2 w straight above the hinge line
    const Hinge h;
    BodyBlend plain(h.boundary, h.bodyOf, {Eigen::Vector3d::Zero()});
    plain.setStar(0, 0.25, 0.1);
    EXPECT_THROW(plain.weights(h.boundary), Error);

    BodyBlend hinge(h.boundary, h.bodyOf, {Eigen::Vector3d::Zero()});
    hinge.setHinge(0, {0, 0, 2}, h.partner, 0.25, 0.1);
    Points probe(4, 3);
    probe << 0.9, 0, 0,   -1.0, 0, 0,   0, 0.5, 0,   0, 5, 0;
    const Eigen::MatrixXd w = hinge.weights(probe);
    EXPECT_NEAR(w(0, 0), 1, 1e-14);
    EXPECT_NEAR(w(1, 0), 0, 1e-14);
    EXPECT_NEAR(w(2, 0), 0.5, 1e-14);    // r 0.5 < R_in: the ring's w is 1
    EXPECT_EQ(w(3, 0), 0);
}


TEST(BodyBlend, HingeTurnsACircleAboutItsAxisWithoutFolding)
{
    // the map phi -> phi + a s(phi) on a circle about the hinge line keeps
    // the circle's order up to a = 100 deg (d s/d phi >= -1/2: 1 + a ds/dphi
    // > 0 below 2 rad), and every point keeps its radius
    const Hinge h;
    BodyBlend hinge(h.boundary, h.bodyOf, {Eigen::Vector3d::Zero()});
    hinge.setHinge(0, {0, 0, 1}, h.partner, 0.25, 0.1);
    RigidMotion m;
    m.rotation = {0, 0, 100*EIGEN_PI/180};
    const int n = 720;
    Points x = ring(n, 0.5);
    Values d;
    blendedRigidDisplacement({m}, x, hinge.weights(x), d);
    double last = -1e300;
    for (int k = 0; k < n; ++k)
    {
        // start just past the wing's side (phi = pi), go once round
        const int i = (k + n/2 + 1) % n;
        const Eigen::Vector3d q(x.row(i) + d.row(i));
        EXPECT_NEAR(q.norm(), 0.5, 1e-13);
        double phi = std::atan2(q.y(), q.x());
        while (phi < last - EIGEN_PI) phi += 2*EIGEN_PI;
        EXPECT_GT(phi, last) << "fold at point " << i;
        last = phi;
    }
}


TEST(BodyBlend, HingeRefusesAPartnerOnTheBodyAZeroAxisNoSide)
{
    const Hinge h;
    BodyBlend blend(h.boundary, h.bodyOf, {Eigen::Vector3d::Zero()});
    std::vector<bool> onBody(h.partner);
    onBody[0] = true;
    EXPECT_THROW(blend.setHinge(0, {0, 0, 1}, onBody, 0.25, 0.1), Error);
    EXPECT_THROW(blend.setHinge(0, {0, 0, 0}, h.partner, 0.25, 0.1), Error);
    // the axis along the flap: its centroid is on it
    EXPECT_THROW(blend.setHinge(0, {1, 0, 0}, h.partner, 0.25, 0.1), Error);
    EXPECT_THROW(blend.setHinge(0, {0, 0, 1}, std::vector<bool>(3), 0.25, 0.1), Error);
}
