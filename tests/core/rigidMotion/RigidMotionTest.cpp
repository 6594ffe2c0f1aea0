// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the rigid fit (fitRigidMotion), the rotation vectors and the
// blended rigid motion of several bodies.
#include "BlendedRigidMotion.hpp"
#include "RigidFit.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

using namespace dcprbf;

namespace
{

const double pi = EIGEN_PI;

//- Displacements of x0 under x -> pivot + R (x - pivot) + shift
Values moved
(
    const Points& x0,
    const Eigen::Vector3d& omega,
    const Eigen::Vector3d& pivot,
    const Eigen::Vector3d& shift
)
{
    const Eigen::Matrix3d R = rotationMatrix(omega);
    Values d(x0.rows(), 3);
    for (Eigen::Index i = 0; i < x0.rows(); ++i)
    {
        const Eigen::Vector3d x(x0.row(i).transpose());
        d.row(i) = (pivot + R*(x - pivot) + shift - x).transpose();
    }
    return d;
}

} // namespace


TEST(RigidFit, RecoversA3DRigidMotion)
{
    const Points x0 = test::randomPoints(40, 3, 7);
    const Eigen::Vector3d omega = 1.1*Eigen::Vector3d(1, -2, 0.5).normalized();
    const Values d = moved(x0, omega, {0.3, 0.2, -0.1}, {0.5, -1, 2});
    const RigidMotion m = fitRigidMotion(x0, d, 3);
    EXPECT_LT((m.rotation - omega).norm(), 1e-12);
    EXPECT_LT(m.rmsResidual, 1e-12);
    for (Eigen::Index i = 0; i < x0.rows(); ++i)
    {
        EXPECT_LT((m.displacement(x0.row(i).transpose()) - d.row(i).transpose()).norm(), 1e-12);
    }
}


TEST(RigidFit, AboutAnotherCentreIsTheSameMotion)
{
    const Points x0 = test::randomPoints(10, 3, 4);
    const Values d = moved(x0, {0.3, 2.0, -1.0}, {0.25, 0, 0}, {0.1, 0.2, 0.3});
    const RigidMotion m = fitRigidMotion(x0, d, 3);
    const RigidMotion p = m.about({0.25, 0, 0});
    EXPECT_LT((p.translation - Eigen::Vector3d(0.1, 0.2, 0.3)).norm(), 1e-12);
    for (Eigen::Index i = 0; i < x0.rows(); ++i)
    {
        const Eigen::Vector3d x(x0.row(i).transpose());
        EXPECT_LT((p.displacement(x) - m.displacement(x)).norm(), 1e-12);
    }
}


TEST(RigidFit, TwoDimensionalAngleGrowsPastHalfATurn)
{
    const Points x0 = test::randomPoints(30, 2, 3);
    Eigen::Vector3d previous(Eigen::Vector3d::Zero());
    for (int deg = 10; deg <= 400; deg += 10)
    {
        const double a = deg*pi/180;
        const Values d = moved(x0, {0, 0, a}, {0.25, 0, 0}, {0, 0.1, 0});
        const RigidMotion m = fitRigidMotion(x0, d, 2, previous);
        ASSERT_NEAR(m.rotation.z(), a, 1e-12) << deg << " deg";
        EXPECT_EQ(m.rotation.x(), 0);
        EXPECT_LT(m.rmsResidual, 1e-12);
        previous = m.rotation;
    }
    // turning back: the angle decreases continuously too
    const Values d = moved(x0, {0, 0, 350*pi/180}, {0.25, 0, 0}, {0, 0.1, 0});
    EXPECT_NEAR(fitRigidMotion(x0, d, 2, previous).rotation.z(), 350*pi/180, 1e-12);
}


TEST(RigidFit, ThreeDimensionalAngleGrowsPastHalfATurn)
{
    const Points x0 = test::randomPoints(30, 3, 5);
    const Eigen::Vector3d axis = Eigen::Vector3d(0.3, 1, -0.2).normalized();
    Eigen::Vector3d previous(Eigen::Vector3d::Zero());
    for (int deg = 15; deg <= 720; deg += 15)
    {
        const Eigen::Vector3d omega = (deg*pi/180)*axis;
        const RigidMotion m = fitRigidMotion(x0, moved(x0, omega, {1, 0, 0}, {0, 0, 0}), 3, previous);
        ASSERT_LT((m.rotation - omega).norm(), 1e-10) << deg << " deg";
        previous = m.rotation;
    }
}


TEST(RigidFit, ResidualIsTheNonRigidPart)
{
    const Points x0 = test::randomPoints(50, 3, 11);
    Values d = moved(x0, {0.2, 0.1, -0.3}, {0, 0, 0}, {1, 2, 3});
    Values bump(Values::Zero(x0.rows(), 3));
    bump(0, 0) = 1e-3;  // one point off the rigid motion
    const RigidMotion m = fitRigidMotion(x0, d + bump, 3);
    EXPECT_GT(m.rmsResidual, 1e-3/std::sqrt(50.0)*0.5);
    EXPECT_LT(m.rmsResidual, 1e-3/std::sqrt(50.0));
}


TEST(RigidFit, RefusesIllPosedInput)
{
    const Points x0 = test::randomPoints(5, 3, 1);
    EXPECT_THROW(fitRigidMotion(Points(0, 3), Values(0, 3), 3), Error);
    EXPECT_THROW(fitRigidMotion(x0, Values::Zero(4, 3), 3), Error);
    Values bad(Values::Zero(5, 3));
    bad(2, 1) = std::nan("");
    EXPECT_THROW(fitRigidMotion(x0, bad, 3), Error);
    EXPECT_THROW(fitRigidMotion(x0, Values::Zero(5, 3), 4), Error);
}


TEST(BlendedRigidMotion, WeightOneIsTheBodyAndZeroIsRest)
{
    const Points x = test::randomPoints(20, 3, 2);
    RigidMotion body;
    body.centre = {0.5, 0.5, 0.5};
    body.rotation = {0, 2.5, 0};
    body.translation = {0.1, 0, -0.2};
    Eigen::MatrixXd w(20, 1);
    w.setOnes();
    w.bottomRows(10).setZero();
    Values out;
    blendedRigidDisplacement({body}, x, w, out);
    for (Eigen::Index i = 0; i < 10; ++i)
    {
        EXPECT_LT((out.row(i).transpose() - body.displacement(x.row(i).transpose())).norm(), 1e-14);
    }
    EXPECT_EQ(out.bottomRows(10).cwiseAbs().maxCoeff(), 0);
}


TEST(BlendedRigidMotion, HalfWeightTurnsHalfAboutTheCentre)
{
    RigidMotion body;
    body.centre = {0.25, 0, 0};
    body.rotation = {0, 0, 0.8*pi};
    body.translation = {0, 0.4, 0};
    Points x(1, 3);
    x << 1.25, 0, 0;
    Values out;
    blendedRigidDisplacement({body}, x, Eigen::MatrixXd::Constant(1, 1, 0.5), out);
    const Eigen::Vector3d expected =
        Eigen::Vector3d(0.25 + std::cos(0.4*pi), std::sin(0.4*pi) + 0.2, 0) - x.row(0).transpose();
    EXPECT_LT((out.row(0).transpose() - expected).norm(), 1e-14);
}


TEST(BlendedRigidMotion, CommonRigidMotionIsExactForAnyPartitionOfUnity)
{
    // two bodies (different centres) moving by one rigid motion, weights
    // summing to 1 in any proportion: every point moves by that motion
    const Points x = test::randomPoints(30, 3, 9, 4.0);
    const Eigen::Vector3d omega(0.4, -2.9, 1.0), pivot(1, 1, 0), shift(0.3, 0.2, 0.1);
    const Points body1 = test::randomPoints(12, 3, 21), body2 = test::randomPoints(9, 3, 22, 3.0);
    std::vector<RigidMotion> bodies
    {
        fitRigidMotion(body1, moved(body1, omega, pivot, shift), 3),
        fitRigidMotion(body2, moved(body2, omega, pivot, shift), 3)
    };
    Eigen::MatrixXd w(30, 2);
    w.col(0) = 0.5*(Eigen::VectorXd::Random(30).array() + 1).matrix();
    w.col(1) = 1 - w.col(0).array();
    Values out;
    blendedRigidDisplacement(bodies, x, w, out);
    EXPECT_LT((out - moved(x, omega, pivot, shift)).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_THROW(blendedRigidDisplacement(bodies, x, Eigen::MatrixXd::Ones(30, 1), out), Error);
}
