/*---------------------------------------------------------------------------*\
  dcpRBF tests: bad dcpRBFCoeffs give a FatalIOError naming the keyword
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "dcpRBFVelocityMotionSolver.H"

#include <gtest/gtest.h>

#include <iostream>
#include <sstream>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

struct badInput
{
    std::string name;       // test name
    std::string coeffs;     // dcpRBFCoeffs body
    std::string expected;   // words the error message must contain
    label dim = 2;          // the box's dimension
};

const std::string ok =
    " function WendlandC2; polynomial true;";

std::vector<badInput> catalogue()
{
    const std::string mv = "movingPatches (bottom);";
    const std::string st = "staticPatches (top left right);";
    const std::string r = "supportRadius 0.5;";
    return
    {
        {"UnknownFunction", mv + st + r + "function Wendland;", "Unknown function Wendland"},
        {"UnknownFunctionListsAllowed", mv + st + r + "function cubic;", "WendlandC2"},
        {"UnknownMovingPatch", "movingPatches (wing);" + st + r, "movingPatches"},
        {"UnknownStaticPatch", mv + "staticPatches (inlet);" + r, "staticPatches"},
        {"MissingMovingPatches", st + r, "movingPatches"},
        {"EmptyMovingPatches", "movingPatches ();" + st + r, "movingPatches"},
        {"PatchInBothLists", mv + "staticPatches (bottom top);" + r, "both"},
        {"EmptyPatchAsMoving", "movingPatches (front);" + st + r, "empty"},
        {"ZeroRadius", mv + st + "supportRadius 0;", "supportRadius"},
        {"NegativeRadius", mv + st + "supportRadius -1;", "supportRadius"},
        {"UnknownKeyword", mv + st + r + "suportRadius 2;", "suportRadius"},
        {"MisspeltRequiredKeyword", mv + st + "suportRadius 0.5;", "Unknown keyword suportRadius"},
        {"MisspeltKeywordNearestSuggested", mv + st + r + "suportRadius 2;", "(did you mean supportRadius?)"},
        {"MisspeltKeywordCaseSuggested", mv + st + "SUPPORTRADIUS 2;", "(did you mean supportRadius?)"},
        {"PolynomialNotBool", mv + st + r + "polynomial maybe;", "polynomial"},
        {"UnknownFarField", mv + st + r + "farField frozen;", "farField"},
        {"UnknownCellZone", mv + st + r + "cellZone nowhere;", "Keyword cellZone: no cellZone nowhere"},
        {"CellZoneNotAName", mv + st + r + "cellZone (a b);", "cellZone"},
        {"FarFieldStillWithoutStaticPoints", mv + "staticPatches ();" + r + "farField still;", "farField still has no effect without static points"},
        {"FarFieldStillWithRotation", mv + st + r + "farField still; rotationInterpolation true;", "farField still has no effect with rotationInterpolation"},
        {"TPSWithoutPolynomial", mv + st + r + "function TPS; polynomial false;", "polynomial"},
        {"ControlPointsNotDict", mv + st + r + "controlPoints all;", "controlPoints"},
        {"UnknownSelection", mv + st + r + "controlPoints { selection fancy; }", "selection"},
        {"UnknownControlPointsKeyword", mv + st + r + "controlPoints { selection all; nPoints 3; }", "nPoints"},
        {"MinPointsAboveMaxPoints", mv + st + r + "controlPoints { selection greedy; minPoints 50; maxPoints 10; }", "minPoints"},
        {"ZeroTolerance", mv + st + r + "controlPoints { selection greedy; tolerance 0; }", "tolerance"},
        {"NegativeTolerance", mv + st + r + "controlPoints { selection dynamic; tolerance -1e-3; }", "tolerance"},
        {"NegativeMaxPoints", mv + st + r + "controlPoints { selection greedy; maxPoints -5; }", "maxPoints"},
        {"ReselectBelowTolerance", mv + st + r + "controlPoints { selection greedy; tolerance 0.01; reselectTolerance 0.001; }", "reselectTolerance"},
        {"NSwapWithGreedy", mv + st + r + "controlPoints { selection greedy; nSwap 2; }", "nSwap"},
        {"NegativeNSwap", mv + st + r + "controlPoints { selection dynamic; nSwap -1; }", "nSwap"},
        {"ToleranceWithAll", mv + st + r + "controlPoints { selection all; tolerance 1e-3; }", "tolerance"},
        {"UnknownSelectOn", mv + st + r + "controlPoints { selection greedy; selectOn velocity; }", "selectOn"},
        {"UnknownQualityMetric", mv + st + r + "qualityMetric skewness;", "qualityMetric"},
        {"QualityFloorAboveOne", mv + st + r + "qualityFloor 1.5;", "qualityFloor"},
        {"UnknownFloorAction", mv + st + r + "qualityFloorAction ignore;", "qualityFloorAction"},
        {"NegativeGuardIterations", mv + st + r + "guardIterations -2;", "guardIterations"},
        {"RelativeRadiusUnknownUnit", mv + st + "supportRadius 3 chords;", "movingExtent"},
        {"BoundaryCorrectionNotBool", mv + st + r + "boundaryCorrection sometimes;", "boundaryCorrection"},
        {"NegativeEvaluationMemory", mv + st + r + "evaluationMemoryMB -1;", "evaluationMemoryMB"},
        {"NegativePointsPerThread", mv + st + r + "pointsPerThread -1;", "pointsPerThread"},
        {"UnknownSwapRule", mv + st + r + "controlPoints { selection dynamic; swapRule best; }", "swapRule"},
        {"SwapRuleWithGreedy", mv + st + r + "controlPoints { selection greedy; swapRule nearest; }", "swapRule"},
        {"BlendStepsWithNearest", mv + st + r + "controlPoints { selection dynamic; swapRule nearest; swapBlendSteps 3; }", "swapBlendSteps"},
        {"ZeroBlendSteps", mv + st + r + "controlPoints { selection dynamic; swapBlendSteps 0; }", "swapBlendSteps"},
        {"UnknownTrialPoints", mv + st + r + "controlPoints { selection dynamic; trialPoints some; }", "trialPoints"},
        {"TrialPointsListsAllowed", mv + st + r + "controlPoints { selection dynamic; trialPoints some; }", "window"},
        {"TrialPointsWithNearest", mv + st + r + "controlPoints { selection dynamic; swapRule nearest; trialPoints all; }", "trialPoints"},
        {"TrialPointsWithGreedy", mv + st + r + "controlPoints { selection greedy; trialPoints window; }", "trialPoints"},
        {"TrialPointsWithAll", mv + st + r + "controlPoints { selection all; trialPoints all; }", "Allowed selections using it: dynamic"},
        {"ZeroTrialBackoff", mv + st + r + "controlPoints { selection dynamic; trialBackoff 0; }", "trialBackoff"},
        {"TrialBackoffAboveLongestWait", mv + st + r + "controlPoints { selection dynamic; trialBackoff 17; }", "trialBackoff"},
        {"TrialBackoffWithNearest", mv + st + r + "controlPoints { selection dynamic; swapRule nearest; trialBackoff 2; }", "trialBackoff"},
        {"TrialBackoffWithGreedy", mv + st + r + "controlPoints { selection greedy; trialBackoff 2; }", "trialBackoff"},
        {"ZeroTrialQualityDrop", mv + st + r + "controlPoints { selection dynamic; trialQualityDrop 0; }", "trialQualityDrop"},
        {"TrialQualityDropAboveOne", mv + st + r + "controlPoints { selection dynamic; trialQualityDrop 1.5; }", "trialQualityDrop"},
        {"TrialBackoffWithoutSwaps", mv + st + r + "controlPoints { selection dynamic; nSwap 0; trialBackoff 2; }", "nSwap 0"},
        {"TrialQualityDropWithNearest", mv + st + r + "controlPoints { selection dynamic; swapRule nearest; trialQualityDrop 0.1; }", "trialQualityDrop"},
        {"RotationWithoutRotationInterpolation", mv + st + r + "rotation { centre (0.5 0 0); }", "rotationInterpolation"},
        {"RotationInterpolationNotBool", mv + st + r + "rotationInterpolation maybe;", "rotationInterpolation"},
        {"RotationNotDict", mv + st + r + "rotationInterpolation true; rotation yes;", "rotation"},
        {"RotationUnknownKeyword", mv + st + r + "rotationInterpolation true; rotation { center (0.5 0 0); }", "center"},
        {"RotationBodiesNotDict", mv + st + r + "rotationInterpolation true; rotation { bodies (bottom); }", "bodies"},
        {"RotationCentreBesideBodies", mv + st + r + "rotationInterpolation true; rotation { centre (0 0 0); bodies { b { patches (bottom); } } }", "centre"},
        {"RotationBodyOfStaticPatch", mv + st + r + "rotationInterpolation true; rotation { bodies { b { patches (top); } } }", "movingPatches"},
        {"RotationBodyUnknownPatch", mv + st + r + "rotationInterpolation true; rotation { bodies { b { patches (wing); } } }", "patches"},
        {"RotationBodyUnknownKeyword", mv + st + r + "rotationInterpolation true; rotation { bodies { b { patches (bottom); pivot (0 0 0); } } }", "pivot"},
        {"RotationNoRoomAroundTheCentre", mv + st + r + "rotationInterpolation true; rotation { centre (0.5 0.9 0); }", "no room"},
        {"MovingPatchInNoBody", "movingPatches (bottom left); staticPatches (top right);" + r + "rotationInterpolation true; rotation { bodies { b { patches (bottom); } } }", "in no body"},
        {"TouchingBodies", "movingPatches (bottom left); staticPatches (top right);" + r + "rotationInterpolation true; rotation { bodies { a { patches (bottom); } b { patches (left); } } }", "share boundary"},
        {"UnknownBlendProfile", mv + st + r + "rotationInterpolation true; rotation { blendProfile spiral; }", "blendProfile"},
        {"BlendSlopeWithLogProfile", mv + st + r + "rotationInterpolation true; rotation { blendProfile log; blendSlope 0.1; }", "blendSlope"},
        {"NegativeBlendSlope", mv + st + r + "rotationInterpolation true; rotation { blendSlope -1; }", "blendSlope"},
        {"BlendRampAboveOne", mv + st + r + "rotationInterpolation true; rotation { blendRamp 2; }", "blendRamp"},
        {"RotationAxisIn2D", mv + st + r + "rotationInterpolation true; rotation { centre (0.5 0 0); axis (0 0 1); }", "Keyword axis is for 3D meshes"},
        {"RotationAxisZero3D", mv + st + r + "rotationInterpolation true; rotation { centre (0.5 0 0.5); axis (0 0 0); }", "Keyword axis must be a non-zero vector", 3},
        {"RotationAxisWord3D", mv + st + r + "rotationInterpolation true; rotation { centre (0.5 0 0.5); axis up; }", "Keyword axis must be a non-zero vector", 3},
        {"RotationAxisWithoutCentre3D", mv + st + r + "rotationInterpolation true; rotation { axis (0 0 1); }", "Keyword axis needs centre", 3},
        {"RotationBodyAxisWithoutCentre3D", mv + st + r + "rotationInterpolation true; rotation { bodies { b { patches (bottom); axis (0 0 1); } } }", "Keyword axis needs centre", 3},
        {"RotationAxisBesideBodies", mv + st + r + "rotationInterpolation true; rotation { axis (0 0 1); bodies { b { patches (bottom); } } }", "Keyword axis: with bodies"},
        {"MovingPatchRegexMatchesNothing", "movingPatches (\"wing.*\");" + st + r, "movingPatches"},

        // A new user's mistakes (issue 39), refused at the start, naming
        // the keyword (the 2D box: 3 cells a side, 36 boundary points)
        {"MaxPointsBelowPolynomial2D", mv + st + r + "controlPoints { selection greedy; maxPoints 2; }", "maxPoints 2 is below the 3 control points the linear polynomial needs in 2D"},
        {"MaxPointsOneDynamic", mv + st + r + "controlPoints { selection dynamic; maxPoints 1; }", "maxPoints 1 is below"},
        {"MinPointsAboveCandidates", mv + st + r + "controlPoints { selection greedy; minPoints 500; }", "minPoints 500 is above the"},
        {"RadiusBelowTheCells", mv + st + "supportRadius 0.01;", "supportRadius 0.01 reaches no cell centre"},
        {"RelativeRadiusBelowTheCells", mv + st + "supportRadius 0.001 movingExtent;", "reaches no cell centre"},

        // More: every keyword's type, range and belonging
        {"QualityFloorBelowMinusOne", mv + st + r + "qualityFloor -2;", "qualityFloor"},
        {"QualityFloorOne", mv + st + r + "qualityFloor 1;", "qualityFloor"},
        {"QualityFloorWord", mv + st + r + "qualityFloor high;", "qualityFloor"},
        {"GuardIterationsFraction", mv + st + r + "guardIterations 1.5;", "guardIterations"},
        {"GuardIterationsTooMany", mv + st + r + "guardIterations 100000;", "guardIterations"},
        {"EvaluationMemoryWord", mv + st + r + "evaluationMemoryMB lots;", "evaluationMemoryMB"},
        {"PointsPerThreadFraction", mv + st + r + "pointsPerThread 0.5;", "pointsPerThread"},
        {"FunctionNumber", mv + st + r + "function 2;", "function"},
        {"FunctionLowerCase", mv + st + r + "function wendlandC2;", "Unknown function wendlandC2"},
        {"PolynomialNumber", mv + st + r + "polynomial 2;", "polynomial"},
        {"RadiusWord", mv + st + "supportRadius large;", "supportRadius"},
        {"RadiusInfinite", mv + st + "supportRadius 1e400;", "supportRadius"},
        {"RadiusHuge", mv + st + "supportRadius 1e200;", "supportRadius 1e+200 is no length for this mesh"},
        {"RadiusTiny", mv + st + "supportRadius 1e-200;", "supportRadius 1e-200 is no length for this mesh"},
        {"RelativeRadiusNegative", mv + st + "supportRadius -2 movingExtent;", "supportRadius"},
        {"MovingPatchesWord", "movingPatches bottom;" + st + r, "movingPatches (wing \"flap.*\"); got bottom"},
        {"StaticPatchesWord", mv + "staticPatches top;" + r, "staticPatches"},
        {"MovingPatchesNumber", "movingPatches (1);" + st + r, "movingPatches"},
        {"MissingStaticPatches", mv + r, "staticPatches"},
        {"EmptyPatchAsStatic", mv + "staticPatches (top front);" + r, "empty"},
        {"QualityMetricNumber", mv + st + r + "qualityMetric 1;", "qualityMetric"},
        {"FloorActionAbort", mv + st + r + "qualityFloorAction abort;", "qualityFloorAction"},
        {"BoundaryCorrectionNumber", mv + st + r + "boundaryCorrection 3;", "boundaryCorrection"},
        {"SelectionNumber", mv + st + r + "controlPoints { selection 2; }", "selection"},
        {"SelectionCapitalised", mv + st + r + "controlPoints { selection Greedy; }", "selection"},
        {"ToleranceWord", mv + st + r + "controlPoints { selection greedy; tolerance small; }", "tolerance"},
        {"ToleranceAboveOne", mv + st + r + "controlPoints { selection greedy; tolerance 2; }", "tolerance"},
        {"MinPointsNegative", mv + st + r + "controlPoints { selection greedy; minPoints -1; }", "minPoints"},
        {"MinPointsFraction", mv + st + r + "controlPoints { selection greedy; minPoints 2.5; }", "minPoints"},
        {"MaxPointsZero", mv + st + r + "controlPoints { selection greedy; maxPoints 0; }", "maxPoints"},
        {"MaxPointsWord", mv + st + r + "controlPoints { selection greedy; maxPoints many; }", "maxPoints"},
        {"MinPointsWithAll", mv + st + r + "controlPoints { selection all; minPoints 5; }", "minPoints"},
        {"MaxPointsWithAll", mv + st + r + "controlPoints { selection all; maxPoints 5; }", "maxPoints"},
        {"DoubleEdgedWithAll", mv + st + r + "controlPoints { selection all; doubleEdged true; }", "doubleEdged"},
        {"DoubleEdgedNumber", mv + st + r + "controlPoints { selection greedy; doubleEdged 2; }", "doubleEdged"},
        {"SelectOnWithAll", mv + st + r + "controlPoints { selection all; selectOn unit; }", "selectOn"},
        {"ReselectToleranceWithAll", mv + st + r + "controlPoints { selection all; reselectTolerance 0.1; }", "reselectTolerance"},
        {"ReselectToleranceWord", mv + st + r + "controlPoints { selection greedy; reselectTolerance none; }", "reselectTolerance"},
        {"NSwapWithAll", mv + st + r + "controlPoints { selection all; nSwap 2; }", "nSwap"},
        {"NSwapFraction", mv + st + r + "controlPoints { selection dynamic; nSwap 0.5; }", "nSwap"},
        {"NSwapTooMany", mv + st + r + "controlPoints { selection dynamic; nSwap 5000; }", "nSwap"},
        {"ProtectStepsWithGreedy", mv + st + r + "controlPoints { selection greedy; protectSteps 2; }", "protectSteps"},
        {"ProtectStepsNegative", mv + st + r + "controlPoints { selection dynamic; protectSteps -1; }", "protectSteps"},
        {"SwapRuleWithAll", mv + st + r + "controlPoints { selection all; swapRule errorGuided; }", "swapRule"},
        {"SwapRuleNumber", mv + st + r + "controlPoints { selection dynamic; swapRule 1; }", "swapRule"},
        {"BlendStepsWithGreedy", mv + st + r + "controlPoints { selection greedy; swapBlendSteps 2; }", "swapBlendSteps"},
        {"BlendStepsTooMany", mv + st + r + "controlPoints { selection dynamic; swapBlendSteps 5000; }", "swapBlendSteps"},
        {"TrialBackoffFraction", mv + st + r + "controlPoints { selection dynamic; trialBackoff 2.5; }", "trialBackoff"},
        {"TrialQualityDropNegative", mv + st + r + "controlPoints { selection dynamic; trialQualityDrop -0.1; }", "trialQualityDrop"},
        {"TrialQualityDropWithGreedy", mv + st + r + "controlPoints { selection greedy; trialQualityDrop 0.1; }", "trialQualityDrop"},
        {"ControlPointsList", mv + st + r + "controlPoints (greedy);", "controlPoints"},
        {"ControlPointsMisspelt", mv + st + r + "controlPoint { selection greedy; }", "controlPoint"},
        {"RotationCentreWord", mv + st + r + "rotationInterpolation true; rotation { centre middle; }", "centre"},
        {"RotationCentreTwoComponents", mv + st + r + "rotationInterpolation true; rotation { centre (0.5 0.5); }", "centre"},
        {"RotationBodyWithoutPatches", mv + st + r + "rotationInterpolation true; rotation { bodies { b { centre (0.5 0 0); } } }", "patches"},
        {"RotationBodyEmptyPatches", mv + st + r + "rotationInterpolation true; rotation { bodies { b { patches (); } } }", "Keyword patches is an empty list"},
        {"RotationBlendSlopeWord", mv + st + r + "rotationInterpolation true; rotation { blendSlope steep; }", "blendSlope"},
        {"RotationBlendRampNegative", mv + st + r + "rotationInterpolation true; rotation { blendRamp -0.5; }", "blendRamp"},
        {"RotationBlendProfileNumber", mv + st + r + "rotationInterpolation true; rotation { blendProfile 2; }", "blendProfile"},
        {"RotationInterpolationNumber", mv + st + r + "rotationInterpolation 2;", "rotationInterpolation"},
        {"RotationWithoutInterpolationFalse", mv + st + r + "rotationInterpolation false; rotation { centre (0.5 0 0); }", "rotationInterpolation"},
    };
}

class BadInput : public ::testing::TestWithParam<badInput> {};

TEST_P(BadInput, FatalIOErrorNamesTheKeyword)
{
    const badInput& b = GetParam();
    testCase c(b.dim, 3, b.coeffs);
    try
    {
        autoPtr<motionSolver> ms(select(c));
        FAIL() << "no error for: " << b.coeffs;
    }
    catch (const Foam::IOerror& e)
    {
        EXPECT_NE(e.message().find(b.expected), std::string::npos)
            << "message: " << e.message();
    }
}

INSTANTIATE_TEST_SUITE_P
(
    Catalogue, BadInput, ::testing::ValuesIn(catalogue()),
    [](const auto& info) { return info.param.name; }
);


// A keyword far from every known one gets no guess (only the allowed list)
TEST(BadInput, UnknownKeywordFarFromAnyHasNoGuess)
{
    testCase c(2, 3, "movingPatches (bottom); staticPatches (top left right); supportRadius 0.5; smoothness 3;");
    try
    {
        autoPtr<motionSolver> ms(select(c));
        FAIL() << "no error for an unknown keyword";
    }
    catch (const Foam::IOerror& e)
    {
        EXPECT_NE(e.message().find("Unknown keyword smoothness"), std::string::npos) << e.message();
        EXPECT_EQ(e.message().find("did you mean"), std::string::npos) << e.message();
    }
}


// Without dcpRBFCoeffs (the settings at the top level, or the sub-dictionary
// misnamed) the error names dcpRBFCoeffs, not a top-level keyword
// dcpRBF's keywords outside dcpRBFCoeffs (at the top level, or with only
// the legacy selection keyword "solver"), or in a misnamed sub-dictionary,
// are refused naming them (without dcpRBFCoeffs every setting is at its
// default: a misplaced one would be ignored)
TEST(BadInput, MisplacedCoeffsAreNamed)
{
    testCase c(2, 3, "movingPatches (bottom); staticPatches (top left right); supportRadius 0.5;");
    for
    (
        const word& misnamed :
        {word::null, word("dcpRBFCoeff"), word("dcpRbfCoeffs"), word("solver")}
    )
    {
        IOdictionary d(c.dynamicMeshDict());
        const dictionary coeffs(d.subDict("dcpRBFCoeffs"));
        d.remove("dcpRBFCoeffs");
        if (misnamed == "solver")
        {
            d.remove("dynamicFvMesh");
            d.remove("motionSolver");
            d.add("solver", word("dcpRBF"));
            d.merge(coeffs);
        }
        else if (misnamed.empty())
        {
            d.merge(coeffs);
        }
        else
        {
            d.add(misnamed, coeffs);
        }
        try
        {
            autoPtr<motionSolver> ms(motionSolver::New(c.mesh(), d));
            FAIL() << "no error with " << (misnamed.empty() ? "the keywords at the top level" : misnamed.c_str());
        }
        catch (const Foam::IOerror& e)
        {
            const std::string expected
            (
                misnamed.size() && misnamed != "solver"
              ? "Found " + misnamed + " in" : "Keyword movingPatches outside dcpRBFCoeffs"
            );
            EXPECT_NE(e.message().find(expected), std::string::npos)
                << "message: " << e.message();
        }
    }
}

// DCPRBF_SIMD_WIDTH with a word it does not know (avx2): a FatalError
// naming the variable and what is allowed, not silently ignored
TEST(BadInput, UnknownSimdWidthWordIsNamed)
{
    testCase c(2, 3, "movingPatches (bottom); staticPatches (top left right); supportRadius 0.5;");
    const std::string before(getEnv("DCPRBF_SIMD_WIDTH"));
    setEnv("DCPRBF_SIMD_WIDTH", "avx2", true);
    try
    {
        autoPtr<motionSolver> ms(select(c));
        setEnv("DCPRBF_SIMD_WIDTH", before, true);
        FAIL() << "no error for DCPRBF_SIMD_WIDTH=avx2";
    }
    catch (const Foam::error& e)
    {
        setEnv("DCPRBF_SIMD_WIDTH", before, true);
        EXPECT_NE(e.message().find("DCPRBF_SIMD_WIDTH is \"avx2\": not a width in bits"), std::string::npos)
            << "message: " << e.message();
    }
}

// Neither a point displacement nor a point velocity: the error says what
// dcpRBF reads, not only OpenFOAM's "cannot find file"
TEST(BadInput, NoPointDisplacementNorVelocityIsNamed)
{
    testCase c(2, 3, "movingPatches (bottom); staticPatches (top left right); supportRadius 0.5;");
    rm(c.dir()/"0/pointDisplacement");
    try
    {
        autoPtr<motionSolver> ms(select(c));
        FAIL() << "no error without 0/pointDisplacement";
    }
    catch (const Foam::error& e)
    {
        for (const char* says : {"pointDisplacement (a pointVectorField", "point velocity pointMotionU (a pointVectorField)", "keyword component", "there is none of them in 0/"})
        {
            EXPECT_NE(e.message().find(says), std::string::npos) << "message: " << e.message();
        }
    }
}

// A velocity solver's case (0/pointMotionU, no 0/pointDisplacement):
// motionSolver dcpRBF selects the velocity-driven solver, a
// velocityMotionSolver (what interfaceTrackingFvMesh casts to); without
// patch lists every patch whose velocity condition fixes the value moves
TEST(Velocity, PointMotionUSelectsTheVelocityDrivenSolver)
{
    testCase c(2, 3, "supportRadius 0.5;");
    rm(c.dir()/"0/pointDisplacement");
    c.write
    (
        "0/pointMotionU", "pointVectorField",
        "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
        "boundaryField { bottom { type fixedValue; value uniform (0 1 0); }"
        " \"(top|left)\" { type fixedValue; value uniform (0 0 0); }"
        " right { type slip; } \"(front|back)\" { type empty; } }\n"
    );
    autoPtr<motionSolver> ms(select(c));
    ASSERT_TRUE(isA<velocityMotionSolver>(ms()));
    EXPECT_EQ(ms->type(), word("dcpRBFVelocity"));
    const dcpRBFSettings& s =
        refCast<const dcpRBFVelocityMotionSolver>(ms()).displacement().settings();
    const polyBoundaryMesh& patches = c.mesh().boundaryMesh();
    labelList fixedValues
    ({
        patches.findPatchID("bottom"), patches.findPatchID("top"),
        patches.findPatchID("left")
    });
    Foam::sort(fixedValues);
    EXPECT_EQ(s.movingPatchIDs(), fixedValues);
    EXPECT_TRUE(s.staticPatchIDs().empty());
}

// A velocity case whose velocity fixes no patch's value, without patch
// lists: refused, naming the velocity field the roles were inferred from
TEST(Velocity, NothingPrescribedRefusedNamingTheVelocity)
{
    testCase c(2, 3, "supportRadius 0.5;");
    rm(c.dir()/"0/pointDisplacement");
    c.write
    (
        "0/pointMotionU", "pointVectorField",
        "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
        "boundaryField { \".*\" { type slip; }"
        " \"(front|back)\" { type empty; } }\n"
    );
    try
    {
        autoPtr<motionSolver> ms(select(c));
        FAIL() << "no error when no patch's velocity is prescribed";
    }
    catch (const Foam::IOerror& e)
    {
        EXPECT_NE(e.message().find("no patch's pointMotionU condition prescribes motion (fixed-value kinds)"), std::string::npos) << e.message();
    }
}

// A pointMotionU beside the pointDisplacement of a displacement case: the
// displacement drives the motion, and the log says the velocity is not read
TEST(Velocity, PointMotionUBesideAPointDisplacementSaidNotRead)
{
    testCase c(2, 3, "movingPatches (bottom); staticPatches (top left right); supportRadius 0.5;");
    c.write
    (
        "0/pointMotionU", "pointVectorField",
        "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
        "boundaryField { \".*\" { type fixedValue; value uniform (0 0 0); }"
        " \"(front|back)\" { type empty; } }\n"
    );
    autoPtr<motionSolver> ms;
    const std::string log(captured([&]() { ms = select(c); }));
    EXPECT_TRUE(isA<dcpRBFMotionSolver>(ms()));
    EXPECT_FALSE(isA<velocityMotionSolver>(ms()));
    EXPECT_NE(log.find("pointDisplacement and pointMotionU in 0/: the displacement drives the motion, the velocity is not read"), std::string::npos) << log;
}

// Mesh class interfaceTrackingFvMesh (it sets the free surface's velocity
// and casts its motion solver to velocityMotionSolver): the velocity-driven
// solver, even with a pointDisplacement left in 0/ (without one: as any
// velocity case, Velocity.PointMotionUSelectsTheVelocityDrivenSolver)
TEST(Velocity, InterfaceTrackingMeshClassSelectsTheVelocityDrivenSolver)
{
    testCase c(2, 3, "movingPatches (bottom); staticPatches (top left right); supportRadius 0.5;");
    c.write
    (
        "0/pointMotionU", "pointVectorField",
        "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
        "boundaryField { \".*\" { type fixedValue; value uniform (0 0 0); }"
        " \"(front|back)\" { type empty; } }\n"
    );
    c.write
    (
        "constant/dynamicMeshDict", "dictionary",
        "dynamicFvMesh interfaceTrackingFvMesh;\nmotionSolver dcpRBF;\n"
        "dcpRBFCoeffs { movingPatches (bottom); staticPatches (top left right);"
        " supportRadius 0.5; }\n"
    );
    autoPtr<motionSolver> ms(select(c));
    EXPECT_TRUE(isA<velocityMotionSolver>(ms()));
}

// dynamicMeshDict edited while running (runTimeModifiable: OpenFOAM calls
// read()): the run keeps its settings and a warning names every entry that
// changed, a keyword dcpRBF does not know included; nothing changed: silence
TEST(BadInput, EditWhileRunningIsNamed)
{
    const std::string coeffs
    (
        "movingPatches (bottom); staticPatches (top left right);"
        " controlPoints { selection greedy; }"
    );
    testCase c(2, 3, coeffs + " supportRadius 0.5;");
    autoPtr<motionSolver> ms(select(c));
    const auto reread = [&](const std::string& now)
    {
        c.write
        (
            "constant/dynamicMeshDict", "dictionary",
            "dynamicFvMesh dynamicMotionSolverFvMesh;\nmotionSolver dcpRBF;\n"
            "dcpRBFCoeffs\n{\n" + now + "\n}\n"
        );
        bool ok = false;
        const std::string log(captured([&]() { ok = ms->read(); }));
        EXPECT_TRUE(ok);
        return log;
    };
    EXPECT_EQ(reread(coeffs + " supportRadius 0.5;"), "");
    const std::string log
    (
        reread
        (
            "movingPatches (bottom); staticPatches (top left right);"
            " controlPoints { selection dynamic; } supportRadius 0.8; bogusKeyword 1;"
        )
    );
    for
    (
        const char* says :
        {
            "dcpRBFCoeffs changed while running (controlPoints/selection greedy -> dynamic,"
            " supportRadius 0.5 -> 0.8, bogusKeyword (none) -> 1)",
            "this run goes on with those"
        }
    )
    {
        EXPECT_NE(log.find(says), std::string::npos) << "log: " << log;
    }
    const auto& solver = refCast<const dcpRBFMotionSolver>(ms());
    EXPECT_EQ(solver.settings().kernel().radius(), 0.5);
    // edited back as the run started: nothing to say
    EXPECT_EQ(reread(coeffs + " supportRadius 0.5;"), "");
}

} // namespace

// ************************************************************************* //
