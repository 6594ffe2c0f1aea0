/*---------------------------------------------------------------------------*\
  dcpRBF tests: bad dcpRBFCoeffs give a FatalIOError naming the keyword
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

struct badInput
{
    std::string name;       // test name
    std::string coeffs;     // dcpRBFCoeffs body
    std::string expected;   // words the error message must contain
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
        {"MissingRadius", mv + st, "supportRadius"},
        {"UnknownKeyword", mv + st + r + "suportRadius 2;", "suportRadius"},
        {"MisspeltRequiredKeyword", mv + st + "suportRadius 0.5;", "Unknown keyword suportRadius"},
        {"PolynomialNotBool", mv + st + r + "polynomial maybe;", "polynomial"},
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
        {"MovingPatchRegexMatchesNothing", "movingPatches (\"wing.*\");" + st + r, "movingPatches"},
    };
}

class BadInput : public ::testing::TestWithParam<badInput> {};

TEST_P(BadInput, FatalIOErrorNamesTheKeyword)
{
    const badInput& b = GetParam();
    testCase c(2, 3, b.coeffs);
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


// Without dcpRBFCoeffs (the settings at the top level, or the sub-dictionary
// misnamed) the error names dcpRBFCoeffs, not a top-level keyword
TEST(BadInput, MissingCoeffsDictionaryIsNamed)
{
    testCase c(2, 3, "movingPatches (bottom); staticPatches (top left right); supportRadius 0.5;");
    // at the top level; misnamed; at the top level with only the legacy
    // selection keyword "solver" (no dynamicFvMesh, no motionSolver)
    for (const word& misnamed : {word::null, word("dcpRBFCoeff"), word("solver")})
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
            FAIL() << "no error without dcpRBFCoeffs";
        }
        catch (const Foam::IOerror& e)
        {
            EXPECT_NE(e.message().find("No dcpRBFCoeffs sub-dictionary"), std::string::npos)
                << "message: " << e.message();
            if (misnamed == "dcpRBFCoeff")
            {
                EXPECT_NE(e.message().find("found dcpRBFCoeff:"), std::string::npos)
                    << "message: " << e.message();
            }
        }
    }
}

} // namespace

// ************************************************************************* //
