/*---------------------------------------------------------------------------*\
  dcpRBF tests: the wingBendingTwistDisplacement point patch condition
  (dcpRBFWingMotion): root fixed, twist axis only deflected, eta^2 bending,
  linear twist, Function1 time laws, clone, FatalIOError on bad entries
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "dcpRBFWingMotion.H"
#include "wingBendingTwistDisplacementPointPatchVectorField.H"
#include "StringStream.H"
#include "pointFields.H"

#include <gtest/gtest.h>
#include <sstream>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

std::string str(const vector& v)
{
    std::ostringstream os;
    os << '(' << v.x() << ' ' << v.y() << ' ' << v.z() << ')';
    return os.str();
}

dictionary dict(const std::string& s)
{
    return dictionary(IStringStream(s)());
}

// Swept wing along y: root at the origin, semi-span 2, deflection along z,
// twist axis through (0.25 0 0) swept by (0.5 1 0)
const std::string swept =
    "root (0 0 0); spanAxis (0 2 0); deflectionDirection (0 0 1);"
    " semiSpan 2; twistAxisPoint (0.25 0 0); twistAxisDirection (0.5 1 0);";

// The twist-axis point at span coordinate y
point axisAt(const scalar y) { return point(0.25 + 0.5*y, y, 0); }

const scalar W = 0.3;                                       // tip deflection
const scalar Theta = 10*constant::mathematical::pi/180;     // tip twist


TEST(WingMotion, RootPointsDoNotMove)
{
    const dcpRBFWingMotion m(dict(swept));
    for (const point& x0 : {point(0, 0, 0), point(1, 0, 0.05), point(-0.3, 0, -0.1)})
    {
        EXPECT_LT(mag(m.displacement(x0, W, Theta)), 1e-15) << str(x0);
    }
}


TEST(WingMotion, TwistAxisPointsMoveOnlyByTheDeflection)
{
    const dcpRBFWingMotion m(dict(swept));
    for (const scalar y : {0.0, 0.4, 1.1, 2.0})
    {
        const scalar eta = y/2;
        const vector d(m.displacement(axisAt(y), W, Theta));
        EXPECT_LT(mag(d - vector(0, 0, W*eta*eta)), 1e-14) << y;
    }
}


TEST(WingMotion, DeflectionDistributions)
{
    const struct { const char* shape; scalar (*f)(scalar); } shapes[] =
    {
        {"quadratic", [](scalar e) { return e*e; }},
        {"cubic", [](scalar e) { return e*e*e; }},
        {"linear", [](scalar e) { return e; }},
        {"uniformLoadBeam", [](scalar e) { return e*e*(6 - 4*e + e*e)/3; }},
    };
    for (const auto& s : shapes)
    {
        const dcpRBFWingMotion m
        (
            dict(swept + " deflectionShape " + s.shape + ";")
        );
        for (const scalar eta : {0.0, 0.1, 0.25, 0.5, 0.8, 1.0})
        {
            // without twist: every point of the station moves alike
            const point x0(axisAt(2*eta) + vector(0.3, 0, 0.02));
            const vector d(m.displacement(x0, W, 0));
            EXPECT_NEAR(d.z(), W*s.f(eta), 1e-14) << s.shape << " eta " << eta;
            EXPECT_LT(mag(d.x()) + mag(d.y()), 1e-15);
        }
        EXPECT_NEAR(s.f(1), 1, 1e-14) << s.shape;
    }

    // beyond the tip and inboard of the root: clipped
    const dcpRBFWingMotion m(dict(swept));
    EXPECT_NEAR(m.displacement(axisAt(2.3), W, 0).z(), W, 1e-14);
    EXPECT_NEAR(m.displacement(axisAt(-0.1), W, 0).z(), 0, 1e-14);
}


// The rotation of a chord section, measured from two of its points (nose-up
// positive, about +y)
scalar chordRotation(const dcpRBFWingMotion& m, scalar y, scalar W, scalar theta)
{
    const point le(axisAt(y) - vector(0.2, 0, 0)), te(axisAt(y) + vector(0.5, 0, 0));
    const vector c0(te - le);
    const vector c(te + m.displacement(te, W, theta) - le - m.displacement(le, W, theta));
    EXPECT_LT(mag(c.y()), 1e-14) << "the section left its plane";
    EXPECT_NEAR(mag(c), mag(c0), 1e-14) << "the chord changed length";
    return std::atan2(-c.z(), c.x());
}


TEST(WingMotion, TwistDistributions)
{
    const dcpRBFWingMotion lin(dict(swept));
    const dcpRBFWingMotion quad(dict(swept + " twistShape quadratic;"));
    for (const scalar eta : {0.0, 0.2, 0.5, 0.75, 1.0})
    {
        // with bending too: bending translates the section
        EXPECT_NEAR(chordRotation(lin, 2*eta, W, Theta), Theta*eta, 1e-13) << eta;
        EXPECT_NEAR(chordRotation(quad, 2*eta, W, Theta), Theta*eta*eta, 1e-13) << eta;
    }
    // the twist axis point of the section stays on the deflected axis
    const vector d(lin.displacement(axisAt(1.0), W, Theta));
    EXPECT_LT(mag(d - vector(0, 0, W*0.25)), 1e-14);
}


TEST(WingMotion, DefaultTwistAxisIsTheSpanAxisThroughTheRoot)
{
    const dcpRBFWingMotion m
    (
        dict("root (1 0 0); spanAxis (0 1 0); deflectionDirection (0 0 -1); semiSpan 1;")
    );
    EXPECT_LT(mag(m.twistAxisAt(point(3, 0.5, 2)) - point(1, 0.5, 0)), 1e-15);
    // a point one unit behind the axis at the tip, twist 90 deg: moves to
    // (0 0 -1) relative to the axis, then down by W
    const vector d(m.displacement(point(2, 1, 0), W, constant::mathematical::piByTwo));
    EXPECT_LT(mag(d - vector(-1, 0, -1 - W)), 1e-14) << str(d);
}


TEST(WingMotion, BadEntriesNameTheKeyword)
{
    const struct { std::string body; std::string expected; } bad[] =
    {
        {"root (0 0 0); spanAxis (0 1 0); deflectionDirection (0 0 1);", "semiSpan"},
        {"root (0 0 0); spanAxis (0 1 0); deflectionDirection (0 0 1); semiSpan -1;", "semiSpan"},
        {"root (0 0 0); spanAxis (0 0 0); deflectionDirection (0 0 1); semiSpan 1;", "spanAxis"},
        {"root (0 0 0); spanAxis (0 1 0); deflectionDirection (0 1 1); semiSpan 1;", "deflectionDirection"},
        {"spanAxis (0 1 0); deflectionDirection (0 0 1); semiSpan 1;", "root"},
        {"root (0 0 0); spanAxis (0 1 0); deflectionDirection (0 0 1); semiSpan 1;"
         " twistAxisDirection (1 0 0);", "twistAxisDirection"},
        {"root (0 0 0); spanAxis (0 1 0); deflectionDirection (0 0 1); semiSpan 1;"
         " deflectionShape parabolic;", "parabolic"},
    };
    for (const auto& b : bad)
    {
        try
        {
            dcpRBFWingMotion m(dict(b.body));
            ADD_FAILURE() << "no error for: " << b.body;
        }
        catch (const Foam::IOerror& e)
        {
            EXPECT_NE(e.message().find(b.expected), std::string::npos)
                << "message: " << e.message();
        }
    }
}


// The condition on a mesh: the bottom patch (y = 0, x and z in [0, 1]) of
// the test box is a wing along x, deflected along y, twisted about z = 0.5
const std::string wingBC =
    "{ type wingBendingTwistDisplacement; root (0 0 0.5); spanAxis (1 0 0);"
    " deflectionDirection (0 1 0); semiSpan 1;"
    " tipDeflection table ((0 0) (1 0.2) (2 0.2));"
    " tipTwist { type sine; frequency 0.25; amplitude 8; scale 1; level 0; }"
    " value uniform (0 0 0); }";

void conditionFollowsTheFunction1sOfTime();

TEST(WingMotion, ConditionFollowsTheFunction1sOfTime)
{
    try
    {
        conditionFollowsTheFunction1sOfTime();
    }
    catch (const Foam::error& e)
    {
        FAIL() << e.message() << " in " << e.functionName() << " " << e.sourceFileName() << ":" << e.sourceFileLineNumber();
    }
}

void conditionFollowsTheFunction1sOfTime()
{
    testCase c(3, 4, "movingPatches (bottom); staticPatches (top left right front back);"
        " supportRadius 1;", "wall", wingBC);
    Time& runTime = c.runTime();
    const polyMesh& mesh = c.mesh();
    pointVectorField pd
    (
        IOobject("pointDisplacement", runTime.timeName(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE),
        pointMesh::New(mesh)
    );
    const label patchi = mesh.boundaryMesh().findPatchID("bottom");
    auto& bc = refCast<wingBendingTwistDisplacementPointPatchVectorField>
    (
        pd.boundaryFieldRef()[patchi]
    );
    const pointField& x0 = mesh.boundaryMesh()[patchi].localPoints();
    ASSERT_EQ(bc.p0().size(), x0.size());

    for (const scalar t : {0.5, 1.0})
    {
        runTime.setTime(t, label(2*t));
        pd.correctBoundaryConditions();
        const vectorField d(static_cast<const vectorField&>(bc));
        const scalar W = 0.2*min(t, 1.0);
        const scalar theta = 8*std::sin(constant::mathematical::twoPi*0.25*t)
            *constant::mathematical::pi/180;
        EXPECT_NEAR(bc.tipDeflection(t), W, 1e-14);
        forAll(x0, i)
        {
            const scalar eta = x0[i].x();
            const vector r(0, 0, x0[i].z() - 0.5);
            // rotation about +x: (0 0 r) -> (0 -r sin, r cos)
            const vector expected
            (
                0,
                W*eta*eta - r.z()*std::sin(theta*eta),
                r.z()*(std::cos(theta*eta) - 1)
            );
            EXPECT_LT(mag(d[i] - expected), 1e-12) << "t " << t << " x0 " << str(x0[i]);
        }
    }

    // clone (with and without the internal field) keeps the motion
    autoPtr<pointPatchField<vector>> copy(bc.clone());
    autoPtr<pointPatchField<vector>> copy2(bc.clone(pd));
    for (const auto* p : {&copy(), &copy2()})
    {
        const auto& w = refCast<const wingBendingTwistDisplacementPointPatchVectorField>(*p);
        EXPECT_NEAR(w.tipDeflection(0.5), 0.1, 1e-14);
        EXPECT_NEAR(w.tipTwist(1), 8, 1e-12);
        EXPECT_EQ(w.p0().size(), x0.size());
    }

    // written and read back: the same condition
    OStringStream os;
    bc.write(os);
    const dictionary written(IStringStream("type wingBendingTwistDisplacement;" + os.str())());
    EXPECT_EQ(written.get<scalar>("semiSpan"), 1);
    EXPECT_TRUE(written.found("p0"));
    EXPECT_TRUE(written.found("tipDeflection"));
    EXPECT_TRUE(written.found("tipTwist"));
}

} // namespace

// ************************************************************************* //
