/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFMemoryReport.H"
#include "dcpRBFResidentMemory.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFMemoryReport::dcpRBFMemoryReport(const bool on)
:
    meshMB_(on ? dcpRBFResidentMemory::residentMB() : -1),
    reported_(std::size_t(-1))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFMemoryReport::report
(
    const std::size_t points,
    const std::size_t candidates
)
{
    label changed = points + candidates != reported_;
    reduce(changed, maxOp<label>());
    if (!changed)
    {
        return;
    }
    reported_ = points + candidates;
    const scalar MB = 1024*1024;
    scalar mesh = meshMB_;
    scalar atPoints = points/MB;
    scalar atCandidates = candidates/MB;
    reduce(mesh, maxOp<scalar>());
    reduce(atPoints, maxOp<scalar>());
    reduce(atCandidates, maxOp<scalar>());
    Info<< "dcpRBF: resident memory by part, largest processor [MB]:"
        << " mesh " << mesh << ", stored matrices " << atPoints
        << " (mesh points) " << atCandidates << " (candidates)" << endl;
}


// ************************************************************************* //
