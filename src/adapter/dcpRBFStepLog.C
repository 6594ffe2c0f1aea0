/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFStepLog.H"
#include "OSspecific.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFStepLog::dcpRBFStepLog(const Time& runTime)
:
    time_(runTime)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFStepLog::write(const record& r)
{
    Info<< "dcpRBF: control points " << r.nControl << " (+" << r.nAdded
        << " -" << r.nRemoved << ", guard +" << r.nGuard;
    if (r.nUndone)
    {
        Info<< ", " << r.nUndone << " trial swap(s) undone";
    }
    Info<< (r.rescue ? ", rescue" : "") << "), quality min "
        << r.minQuality << " mean " << r.meanQuality << " (" << r.nCells
        << " cells in reach), relative boundary error " << r.boundaryError
        << (r.atMaxPoints ? " (at maxPoints)" : "")
        << ", time swap " << r.swapTime << " select " << r.selectTime
        << " interpolate " << r.interpolateTime << " guard " << r.guardTime
        << " points " << r.pointsTime << " s" << endl;

    if (!Pstream::master())
    {
        return;
    }
    if (!file_.valid())
    {
        const fileName dir
        (
            time_.rootPath()/time_.globalCaseName()/"postProcessing"/"dcpRBF"
           /time_.timeName(time_.startTime().value())
        );
        mkDir(dir);
        file_.reset(new OFstream(dir/"dcpRBF.dat"));
        file_()
            << "# dcpRBF motion solver, one row per step" << nl
            << "# time nControl nAdded nRemoved nGuard nCells minQuality"
            << " meanQuality boundaryError atMaxPoints swapTime selectTime"
            << " interpolateTime guardTime nUndone pointsTime" << endl;
    }
    file_()
        << time_.timeName() << ' ' << r.nControl << ' ' << r.nAdded << ' '
        << r.nRemoved << ' ' << r.nGuard << ' ' << r.nCells << ' '
        << r.minQuality << ' ' << r.meanQuality << ' ' << r.boundaryError
        << ' ' << label(r.atMaxPoints) << ' ' << r.swapTime << ' '
        << r.selectTime << ' ' << r.interpolateTime << ' ' << r.guardTime
        << ' ' << r.nUndone << ' ' << r.pointsTime << endl;
}


// ************************************************************************* //
