/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFQualityGuard.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFQualityGuard::dcpRBFQualityGuard
(
    const dcpRBFContext& context,
    dcpRBFControlPoints& controlPoints,
    dcpRBFInterpolation& interpolation,
    dcpRBFQualityMeasurement& quality
)
:
    mesh_(context.mesh()),
    settings_(context.settings()),
    controlPoints_(controlPoints),
    interpolation_(interpolation),
    quality_(quality),
    warnings_(context, controlPoints, interpolation)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFQualityGuard::apply
(
    const dcprbf::Values& d,
    dcpRBFStepState& step
)
{
    const scalar floor = settings_.qualityFloor();
    for (label iter = 0; ; ++iter)
    {
        const dcpRBFQualityRegion::summary& q = quality_.last();

        if (q.checkedMin >= floor || !q.hasLowest)
        {
            warnings_.floorMet();
            break;
        }
        if
        (
            iter >= settings_.guardIterations()
         || !controlPoints_.ready()
         || !controlPoints_.addNear(q.lowest)
        )
        {
            const word t(mesh_.time().timeName());
            const string why(warnings_.guardShortfall(iter));
            if (settings_.onFloorFailure() == dcpRBFSettings::floorAction::stop)
            {
                FatalErrorInFunction
                    << "Time " << t << ": minimum cell quality " << q.checkedMin
                    << " below qualityFloor " << floor << " after " << iter
                    << " guard additions" << why.c_str() << " (" << q.checkedInverted
                    << " inverted cells). Stopping (qualityFloorAction stop)."
                    << exit(FatalError);
            }
            label nShort = 0;
            if (warnings_.shortfallInFull(nShort))
            {
                WarningInFunction
                    << "Time " << t << ": minimum cell quality " << q.checkedMin
                    << " below qualityFloor " << floor << " after " << iter
                    << " guard additions" << why.c_str()
                    << "; continuing (qualityFloorAction warn; under a flow"
                       " solver, qualityFloorAction stop ends the run here)"
                    << (
                           nShort > 1
                         ? ". Short of the floor for "
                           + Foam::name(nShort)
                           + " steps in a row: this warning in full every "
                           + Foam::name(dcpRBFQualityWarnings::warningRepeat)
                           + " steps"
                         : string()
                       ).c_str()
                    << endl;
            }
            break;
        }
        ++step.nGuard;
        controlPoints_.solve(d);
        step.boundaryError = interpolation_.interpolate(d);
        quality_.measure();
    }

    warnings_.warnInverted(quality_.last());
    warnings_.warnLowQuality(quality_.last());
}


// ************************************************************************* //
