/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFKeywords.H"
#include "error.H"
#include "DynamicList.H"

#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using K = Foam::dcpRBFKeyword;
using type = K::valueType;
using scope = K::scope;

//- Unbounded above
constexpr double unbounded = 1e15;

const char* const coeffs = "dcpRBFCoeffs";
const char* const cp = "controlPoints";
const char* const rot = "rotation";
const char* const body = "bodies";
const char* const fvMesh = "dcpRBFFvMeshCoeffs";

//- The table, in the reference's order (docs/keywords.md); made at its
//  first use (static data of other files may read it). A choice read into
//  an enumeration has no words here: those of the Enum, registered beside
//  it (dcpRBFKeyword::choicesFrom), are its allowed words
const std::vector<K>& table()
{
    static const std::vector<K> t
    {
    // dcpRBFCoeffs
    K::other
    (
        coeffs, "movingPatches", type::patches,
        "inferred from the `pointDisplacement` conditions",
        "a non-empty list (may be `()` with a `frame`: a solid body alone);"
        " each entry matches at least one patch or group;"
        " no `empty` or coupled patch; no patch also in `staticPatches`;"
        " both lists or neither",
        "patches whose points follow their pointDisplacement condition"
    ),
    K::other
    (
        coeffs, "staticPatches", type::patches,
        "inferred from the `pointDisplacement` conditions",
        "may be `()`; the same rules as `movingPatches`",
        "patches whose points stay put"
    ),
    K::other
    (
        coeffs, "cellZone", type::name, "the motion solver dictionary's `cellZone` or `cellSet`; none: the whole mesh",
        "an existing cellZone; the same as the motion solver dictionary's if that names one",
        "the region moved and checked; points outside it stay where they are"
    ),
    K::length
    (
        coeffs, "supportRadius", 1e-9, 1e9,
        "the reference mesh's bounding-box diagonal (in the plane of a 2D or"
        " wedge mesh)",
        "reaching at least one cell centre from the moving patches",
        "several times the largest displacement",
        "the kernel's radius (a global function's length scale)"
    ),
    K::choice
    (
        coeffs, "function", "WendlandC2", "the radial basis function"
    ),
    K::onOff
    (
        coeffs, "polynomial", true,
        "add the linear polynomial (affine motions exact)"
    ).alsoNeeds("`TPS` needs `true`"),
    K::other
    (
        coeffs, "controlPoints", type::subDict, "`{}` (`selection`'s default)",
        "the keywords of [`controlPoints`](#controlpoints)",
        "how the control points are chosen"
    ),
    K::choice
    (
        coeffs, "qualityMetric", "sizeShape",
        "the cell quality measured, logged and guarded"
    ),
    K::choice
    (
        coeffs, "qualityScan", "all", "all lowest",
        "every cell's quality each step, or the lowest cells' only"
    ),
    K::real
    (
        coeffs, "qualityFloor", 0, -1, false, 1, false,
        "in-step guard: points join while the minimum quality is below it"
    ).defaultIs("`0` (act on inverted cells)"),
    K::choice
    (
        coeffs, "qualityFloorAction", "warn",
        "when the floor is not met after guardIterations: warn or stop"
    ),
    K::integer
    (
        coeffs, "guardIterations", 5, 0, 1000,
        "at most this many guard additions per step"
    ),
    K::onOff
    (
        coeffs, "boundaryCorrection", true,
        "blend the boundary points' interpolation error into the volume"
    ),
    K::integer
    (
        coeffs, "evaluationMemoryMB", 1024, 0, 1000000,
        "memory per process for stored kernel matrices"
    ).defaultIs("unset: 1024, used once the control set has settled"),
    K::integer
    (
        coeffs, "pointsPerThread", 250000, 0, unbounded,
        "one OpenMP thread per this many mesh points (0: all cores)"
    ),
    K::choice
    (
        coeffs, "farField", "still", "still interpolated",
        "with static points (staticPatches, a region's border): the"
        " displacement blended to zero between"
        " supportRadius and twice it from the moving points, or the"
        " interpolant's own"
    ).defaultIs("`still` (compactly supported functions), `interpolated` (global ones)")
     .alsoNeeds("`still` not with `rotationInterpolation true`, nor without static points"),
    K::other
    (
        coeffs, "frame", type::subDict, "none (the region's frame is still)",
        "`solidBodyMotionFunction` and its coefficients, as OpenFOAM's"
        " solidBody motion solver takes them; on a 2D mesh turning about the"
        " plane's normal and moving within the plane",
        "the region moves as this solid body, dcpRBF morphs it on top"
    ),
    K::onOff
    (
        coeffs, "rotationInterpolation", false,
        "large rotations: the bodies' rigid rotations blended into the volume"
    ),
    K::other
    (
        coeffs, "rotation", type::subDict, "none (`{}`)",
        "the keywords of [`rotation`](#rotation); only with"
        " `rotationInterpolation true`",
        "the bodies and the blend of rotationInterpolation"
    ),

    // controlPoints
    K::choice
    (
        cp, "selection", "all",
        "all boundary points, a greedy set, or a greedy set with swaps"
    ).defaultIs
    (
        "`all` up to 2000 boundary points (`maxPoints`' default), `dynamic`"
        " at its defaults above"
    ),
    K::real
    (
        cp, "tolerance", 1e-3, 0, false, 1, true,
        "the greedy selection's relative boundary error"
    ).only(scope::reduced),
    K::integer
    (
        cp, "minPoints", 0, 0, unbounded, "at least this many control points"
    ).only(scope::reduced).alsoNeeds
    (
        "at most `maxPoints` and at most the boundary points of"
        " `movingPatches` and `staticPatches`"
    ),
    K::integer
    (
        cp, "maxPoints", 2000, 1, unbounded, "at most this many control points"
    ).only(scope::reduced)
     .defaultIs
      (
          "`2000`, at most 1.25e8 over the boundary points (the greedy"
          " basis's numbers: 968 for 129,002) but not below 100, at least"
          " `minPoints`"
      )
     .alsoNeeds("with the polynomial at least dim+1"),
    K::onOff
    (
        cp, "doubleEdged", false,
        "each greedy iteration also adds the worst point of opposite error"
    ).only(scope::reduced),
    K::choice
    (
        cp, "selectOn", "displacement",
        "select on the first displacement, or on a unit one"
    ).only(scope::reduced),
    K::real
    (
        cp, "reselectTolerance", 1e-2, 0, false, unbounded, true,
        "at every step the worst point joins while the error exceeds it"
    ).only(scope::reduced)
     .defaultIs("10 times `tolerance`, at most 1")
     .alsoNeeds("at least `tolerance`"),
    K::choice
    (
        cp, "swapRule", "errorGuided",
        "trial swaps kept if they help, or the paper's rule"
    ).only(scope::dynamic),
    K::integer
    (
        cp, "nSwap", 4, 0, 1000, "swaps (errorGuided: trial swaps) per step"
    ).only(scope::dynamic).defaultIs("`4` (`errorGuided`), `1` (`nearest`)"),
    K::integer
    (
        cp, "swapBlendSteps", 4, 1, 1000,
        "a kept swap is phased in over this many steps"
    ).ofRule("errorGuided"),
    K::choice
    (
        cp, "trialPoints", "window",
        "where a trial's mesh is made"
    ).ofRule("errorGuided"),
    // (its upper bound: errorGuided's longest wait between trials)
    K::integer
    (
        cp, "trialBackoff", 4, 1, 16,
        "steps the next trial waits after an undone one"
    ).ofRule("errorGuided"),
    K::real
    (
        cp, "trialQualityDrop", 0.05, 0, false, 1, true,
        "a wait ends early when the minimum quality falls by more than this"
    ).ofRule("errorGuided"),
    K::integer
    (
        cp, "protectSteps", 3, 0, 1000000,
        "a point that joined fewer steps ago is not removed"
    ).only(scope::dynamic),

    // rotation
    K::other
    (
        rot, "centre", type::position, "the centroid of the body's points",
        "any point; not together with `bodies` (each body then has its own)",
        "the single body's centre of rotation"
    ),
    K::other
    (
        rot, "axis", type::direction, "none",
        "a non-zero vector; 3D only; needs `centre`; not together with"
        " `bodies` (each body then has its own)",
        "the single body's pivot axis through `centre`: the blend is centred"
        " at the point of the axis level with the body's centroid"
    ),
    K::other
    (
        rot, "bodies", type::subDict, "all `movingPatches`, one body",
        "one sub-dictionary per body, at least one"
        " ([below](#bodies-entries)); every moving patch in exactly one body;"
        " bodies must not share points",
        "several bodies, each with its own rigid motion"
    ),
    K::choice
    (
        rot, "blendProfile", "star",
        "the blend's shape: the walls' room, the radial ring, or a hinge"
    ),
    K::real
    (
        rot, "blendSlope", 0.25, 0, true, 10, true,
        "the largest slope of the ring's radii with the angle"
    ).alsoNeeds("only with `blendProfile star` or `hinge`"),
    K::real
    (
        rot, "blendRamp", 0.1, 0, true, 1, true,
        "the share of the blend where its slope rises from 0"
    ).alsoNeeds("only with `blendProfile star` or `hinge`"),
    K::other
    (
        rot, "hingedTo", type::patches, "none",
        "patches not in `movingPatches`; only with `blendProfile hinge`; not"
        " together with `bodies` (each body then has its own)",
        "the static or sliding patches the single body turns on"
    ),

    // an entry of bodies
    K::other
    (
        body, "patches", type::patches, "required",
        "a non-empty list of patches of `movingPatches`; a patch in one body"
        " only",
        "the patches that move together as this body"
    ),
    K::other
    (
        body, "centre", type::position, "the centroid of the body's points",
        "any point", "the body's centre of rotation"
    ),
    K::other
    (
        body, "axis", type::direction, "none",
        "a non-zero vector; 3D only; needs `centre`",
        "the body's pivot axis through `centre`"
    ),
    K::other
    (
        body, "hingedTo", type::patches, "none",
        "patches not in `movingPatches`; only with `blendProfile hinge`",
        "the static or sliding patches the body turns on"
    ),

    // dcpRBFFvMeshCoeffs
    K::choice
    (
        fvMesh, "qualityMetric", "sizeShape",
        "the metric of the cellQuality field"
    )
    };
    return t;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const std::vector<Foam::dcpRBFKeyword>& Foam::dcpRBFKeywords::all()
{
    return table();
}


const Foam::dcpRBFKeyword& Foam::dcpRBFKeywords::get
(
    const word& dictionary,
    const word& name
)
{
    for (const dcpRBFKeyword& k : all())
    {
        if (dictionary == k.dictionary && name == k.name)
        {
            return k;
        }
    }
    FatalErrorInFunction
        << "No keyword " << name << " of " << dictionary << " in dcpRBF's"
        << " keyword table" << abort(FatalError);
    return all()[0];
}


Foam::wordList Foam::dcpRBFKeywords::names(const word& dictionary)
{
    DynamicList<word> list;
    for (const dcpRBFKeyword& k : all())
    {
        if (dictionary == k.dictionary) list.append(k.name);
    }
    return wordList(list);
}


// ************************************************************************* //
