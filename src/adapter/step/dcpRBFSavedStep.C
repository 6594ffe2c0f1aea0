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
    dcpRBFStepMesh& mesh,
    dcpRBFQualityMeasurement& quality,
    scalar& boundaryError
)
:
    mesh_(mesh),
    quality_(quality),
    boundaryError_(boundaryError),
    saved_(mesh.save()),
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
    measurement_.reset(new dcpRBFQualityMeasurement::taken(quality_.take()));
}


void Foam::dcpRBFSavedStep::restore()
{
    if (done_)
    {
        return;
    }
    done_ = true;
    mesh_.restore(std::move(saved_));
    if (measurement_)
    {
        quality_.putBack(std::move(*measurement_));
    }
    boundaryError_ = savedBoundaryError_;
}


// ************************************************************************* //
