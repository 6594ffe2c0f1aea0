/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFStepTimer.H"
#include "dcpRBFQualityMeasurement.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFStepTimer::dcpRBFStepTimer
(
    const dcpRBFQualityMeasurement& quality
)
:
    quality_(quality),
    clock_(),
    checkTime_(quality.checkTime()),
    times_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFStepTimer::start()
{
    clock_.resetTime();
    checkTime_ = quality_.checkTime();
    times_ = times();
}


void Foam::dcpRBFStepTimer::split(scalar times::*part)
{
    const scalar elapsed = clock_.timeIncrement();
    const scalar checks = quality_.checkTime() - checkTime_;
    checkTime_ += checks;
    times_.*part += elapsed - checks;
    times_.measure += checks;
}


// ************************************************************************* //
