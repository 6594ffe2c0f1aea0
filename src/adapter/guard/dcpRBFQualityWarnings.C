/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFQualityWarnings.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFQualityWarnings::dcpRBFQualityWarnings
(
    const dcpRBFContext& context,
    const dcpRBFControlPoints& controlPoints,
    const dcpRBFInterpolation& interpolation
)
:
    mesh_(context.mesh()),
    settings_(context.settings()),
    controlPoints_(controlPoints),
    rotation_(interpolation.rotation().active()),
    prescribed_(interpolation.prescribed()),
    invertedSteps_(0),
    shortfallSteps_(0),
    lowQualityWarned_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::dcpRBFQualityWarnings::guardShortfall(const label iter) const
{
    const label maxN = settings_.selection().maxPoints;
    const label nCandidates = controlPoints_.candidates().rows();
    const string full
    (
        string(" (every boundary point is a control point: more cannot help. ")
      + (
            settings_.kernel().compact()
          ? "The cells are squashed between the moving and the static"
            " patches by the displacement's decay within supportRadius"
            " (about 2 times the displacement over it for WendlandC2):"
            " raise supportRadius"
          : "function " + settings_.kernel().name() + " is global and"
            " supportRadius its shape length: the interpolant is exact at"
            " the boundary points and may swing between them when the"
            " radius is unfit for their spacing: take supportRadius of a"
            " few spacings, or function WendlandC2"
        )
      + (
            prescribed_.slipWalls()
          ? string
            (
                "; sliding (slip) walls near the body: a larger radius carries"
                " more of the motion out to them, list those the body does not"
                " touch under staticPatches or set polynomial false"
            )
          : string()
        )
      + (
            rotation_
          ? ")"
          : "; for large rotations rotationInterpolation true)"
        )
    );
    return
    (
        controlPoints_.size() >= nCandidates
      ? std::string(full)
      : controlPoints_.size() >= maxN
      ? " (the set is at maxPoints " + Foam::name(maxN)
        + ": no point can join; raise maxPoints)"
      : iter >= settings_.guardIterations()
      ? " (guardIterations " + Foam::name(settings_.guardIterations())
        + "; where more points do not raise the minimum, raise"
          " supportRadius"
        + (
              prescribed_.slipWalls()
            ? " or, with sliding walls near the body, list them under"
              " staticPatches)"
            : ")"
          )
      : ""
    );
}


bool Foam::dcpRBFQualityWarnings::inFull(label& count)
{
    return count++ % warningRepeat == 0;
}


bool Foam::dcpRBFQualityWarnings::dynamicCouldHelp() const
{
    // greedy short of the boundary points (with all of them the
    // interpolation is exact there already: dynamic has fewer)
    return
        !settings_.selection().everyCandidate()
     && !settings_.selection().swaps()
     && controlPoints_.size() < controlPoints_.candidates().rows();
}


void Foam::dcpRBFQualityWarnings::warnInverted
(
    const dcpRBFQualityRegion::summary& q
)
{
    if (!q.checkedInverted)
    {
        invertedSteps_ = 0;
        return;
    }
    if (inFull(invertedSteps_))
    {
        // what else could help, from what is not set already
        string hint;
        if (!rotation_)
        {
            hint =
                string(dynamicCouldHelp() ? ", use selection dynamic" : "")
              + (settings_.qualityFloor() > 0 ? "" : ", set a qualityFloor (e.g. 0.2)")
              + (
                    prescribed_.slipWalls() && settings_.polynomial()
                  ? ", with sliding (slip) walls polynomial false (the linear"
                    " part carries the body's rotation or translation out to"
                    " them)"
                  : ""
                )
              + " or, for large rotations, rotationInterpolation true."
              + " (A body moved by the flow, e.g. sixDoFRigidBodyDisplacement,"
                " may itself have moved too far in one step: check its motion.)";
        }
        WarningInFunction
            << "Time " << mesh_.time().timeName() << ": "
            << q.checkedInverted << " inverted or degenerate cells"
            << " (quality <= 0, minimum " << q.checkedMin << "). The mesh is"
            << " invalid: "
            << (
                   rotation_
                 ? "rotationInterpolation: the twist between the bodies and the"
                   " static patches is too large for the cells there (check"
                   " each body's centre is its pivot; refine the cells between"
                   " body and walls, or move the walls away)."
                 : prescribed_.slipWalls()
                 ? "reduce the motion per step; sliding (slip, symmetry) walls"
                   " near the moving patches: list those the body does not"
                   " touch under staticPatches (their points then stay put),"
                   " or take supportRadius nearer the distance from the body"
                   " to them (a larger one carries more of the motion out to"
                   " the walls)"
                 : "reduce the motion per step, enlarge supportRadius"
               )
            << (
                   prescribed_.selfMoved().size()
                 ? ", list the patches moved by their own conditions ("
                   + prescribed_.selfMovedNames() + ") under movingPatches (the cells"
                   " next to them do not follow them)"
                 : string()
               ).c_str()
            << hint.c_str()
            << (
                   invertedSteps_ > 1
                 ? " (Inverted cells for " + Foam::name(invertedSteps_)
                   + " steps in a row: this warning in full every "
                   + Foam::name(warningRepeat) + " steps, each step's dcpRBF"
                     " line counts them.)"
                 : string()
               ).c_str()
            << endl;
    }
}


void Foam::dcpRBFQualityWarnings::warnLowQuality
(
    const dcpRBFQualityRegion::summary& q
)
{
    if
    (
        lowQualityWarned_ || settings_.qualityFloor() > 0
     || !(q.checkedMin < lowQuality && q.checkedMin > 0)
    )
    {
        return;
    }
    lowQualityWarned_ = true;
    WarningInFunction
        << "Time " << mesh_.time().timeName() << ": the minimum cell quality"
        << " fell to " << q.checkedMin << " (1: as the reference mesh's"
        << " cells; said once). The motion is squeezing cells: enlarge"
        << " supportRadius (several times the largest displacement), set a"
        << " qualityFloor (e.g. " << lowQuality << ": control points are"
        << " then added where the cells suffer)"
        << (dynamicCouldHelp() ? ", use selection dynamic" : "")
        << " or reduce the motion per step." << endl;
}


// ************************************************************************* //
