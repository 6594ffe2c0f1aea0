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
#include "OStringStream.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFStepLog::dcpRBFStepLog(const Time& runTime)
:
    time_(runTime)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFStepLog::write(const record& r)
{
    // 4 significant digits for the qualities and the error, 3 for the
    // times in ms, whatever the case's writePrecision
    OStringStream line;
    line.precision(4);
    line<< "dcpRBF: control points " << r.nControl << " (+" << r.nAdded
        << " -" << r.nRemoved << ", guard +" << r.nGuard;
    if (r.nUndone)
    {
        line<< ", " << r.nUndone << " trial swap(s) undone";
    }
    line<< (r.rescue ? ", rescue" : "") << "), quality min "
        << r.minQuality << " mean " << r.meanQuality << " (" << r.nCells
        << " cells in reach), relative boundary error " << r.boundaryError
        << (r.atMaxPoints ? " (at maxPoints)" : "");
    line.precision(3);
    line<< ", time [ms] swap " << 1e3*r.swapTime << " select " << 1e3*r.selectTime
        << " interpolate " << 1e3*r.interpolateTime << " guard " << 1e3*r.guardTime
        << " points " << 1e3*r.pointsTime;
    Info<< line.str().c_str() << endl;

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
