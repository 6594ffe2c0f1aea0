// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the tetrahedron quality metric.
#include "TetQuality.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

using namespace dcprbf;

namespace
{

struct Tet { Eigen::Vector3d p[4]; };

Tet regular()
{
    return {{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
             Eigen::Vector3d(0.5, 0.8, 0), Eigen::Vector3d(0.4, 0.3, 0.9)}};
}

Tet map(const Tet& t, const Eigen::Matrix3d& A, const Eigen::Vector3d& b)
{
    Tet m;
    for (int i = 0; i < 4; ++i) m.p[i] = A*t.p[i] + b;
    return m;
}

TEST(TetQuality, RigidMotionIsOne)
{
    const Tet t = regular();
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    EXPECT_NEAR(TetQuality::compute(t.p, map(t, R, {3, -1, 2}).p), 1.0, 1e-13);
}

TEST(TetQuality, UniformScalingCostsOnlySize)
{
    const Tet t = regular();
    const double s = 1.3;  // volume ratio s^3
    const double q = TetQuality::compute(t.p, map(t, s*Eigen::Matrix3d::Identity(), {0, 0, 0}).p);
    EXPECT_NEAR(q, std::sqrt(1/(s*s*s)), 1e-13);
}

TEST(TetQuality, ShearLowersQualityMonotonically)
{
    const Tet t = regular();
    double last = 1.0;
    for (double g : {0.1, 0.3, 0.6, 1.0, 2.0})
    {
        Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
        S(0, 1) = g;   // volume preserving shear
        const double q = TetQuality::compute(t.p, map(t, S, {0, 0, 0}).p);
        EXPECT_LT(q, last) << g;
        EXPECT_GT(q, 0.0) << g;
        last = q;
    }
}

TEST(TetQuality, InvertedIsNegativeFlatIsZero)
{
    const Tet t = regular();
    Eigen::Matrix3d mirror = Eigen::Matrix3d::Identity();
    mirror(2, 2) = -1;
    EXPECT_NEAR(TetQuality::compute(t.p, map(t, mirror, {0, 0, 0}).p), -1.0, 1e-13);
    Tet flat = t;
    flat.p[3].z() = 0;
    EXPECT_NEAR(TetQuality::compute(t.p, flat.p), 0.0, 1e-15);
}

TEST(TetQuality, DegenerateReferenceIsOne)
{
    Tet flat = regular();
    flat.p[3].z() = 0;
    EXPECT_EQ(TetQuality::compute(flat.p, regular().p), 1.0);
}

} // namespace

namespace
{

TEST(TetQuality, MetricsSeparateSizeAndShape)
{
    const Tet t = regular();
    const double s = 1.3;
    const Tet scaled = map(t, s*Eigen::Matrix3d::Identity(), {0, 0, 0});
    EXPECT_NEAR(TetQuality::compute(t.p, scaled.p, TetQuality::Metric::shape), 1.0, 1e-13);
    EXPECT_NEAR(TetQuality::compute(t.p, scaled.p, TetQuality::Metric::size), 1/(s*s*s), 1e-13);
    Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
    S(0, 1) = 0.5;  // volume preserving
    const Tet sheared = map(t, S, {0, 0, 0});
    EXPECT_NEAR(TetQuality::compute(t.p, sheared.p, TetQuality::Metric::size), 1.0, 1e-13);
    EXPECT_LT(TetQuality::compute(t.p, sheared.p, TetQuality::Metric::shape), 0.95);
}

} // namespace
