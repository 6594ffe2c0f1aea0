/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFSavedStep.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFSavedStep::dcpRBFSavedStep
(
    dcpRBFQualityMeasurement& quality,
    vectorField& displacement,
    scalar& boundaryError
)
:
    quality_(quality),
    displacement_(displacement),
    boundaryError_(boundaryError),
    savedDisplacement_(displacement),
    measured_(quality.measured()),
    savedBoundaryError_(boundaryError),
    done_(false)
{}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::dcpRBFSavedStep::~dcpRBFSavedStep()
{
    restore();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFSavedStep::setMeasurementAside()
{
    measurement_.reset
    (
        new dcpRBFQualityRegion::summary(std::move(quality_.last_))
    );
    measuredPoints_.transfer(quality_.lastPoints_);
}


void Foam::dcpRBFSavedStep::restore()
{
    if (done_)
    {
        return;
    }
    done_ = true;
    displacement_.transfer(savedDisplacement_);
    if (measurement_)
    {
        quality_.last_ = std::move(*measurement_);
        quality_.lastPoints_.transfer(measuredPoints_);
    }
    quality_.measured_ = measured_;
    boundaryError_ = savedBoundaryError_;
}


// ************************************************************************* //
