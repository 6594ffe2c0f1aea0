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
#include "StringStream.H"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFStepLog::dcpRBFStepLog
(
    const Time& runTime,
    const dcpRBFQualityMeasurement& quality
)
:
    time_(runTime),
    quality_(quality),
    clock_(),
    checkTime_(quality.checkTime()),
    times_()
{}


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- A time in s as ms to 3 significant digits, never in exponent form
//  (1020 ms as 1020, 0.00383 ms as 0.00383)
std::string ms(const double seconds)
{
    const double t = 1e3*seconds;
    char buf[64];
    if (t >= 1)
    {
        const int decimals = std::max(0, 2 - int(std::floor(std::log10(t))));
        std::snprintf(buf, sizeof(buf), "%.*f", decimals, t);
    }
    else
    {
        // below 1 ms: 3 significant digits after the leading zeros
        const int decimals = t > 0 ? std::min(12, 2 - int(std::floor(std::log10(t)))) : 0;
        std::snprintf(buf, sizeof(buf), "%.*f", decimals, t);
    }
    return buf;
}

} // namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFStepLog::start()
{
    clock_.resetTime();
    checkTime_ = quality_.checkTime();
    times_ = times();
}


void Foam::dcpRBFStepLog::split(scalar times::*part)
{
    const scalar elapsed = clock_.timeIncrement();
    const scalar checks = quality_.checkTime() - checkTime_;
    checkTime_ += checks;
    times_.*part += elapsed - checks;
    times_.measure += checks;
}


void Foam::dcpRBFStepLog::writeInfo
(
    const dcpRBFStepState& r,
    const dcpRBFQualityRegion::summary& q,
    const bool measured
) const
{
    const times& t = times_;
    // 4 significant digits for the qualities and the error, 3 for the
    // times in ms, whatever the case's writePrecision
    OStringStream line;
    line.precision(4);
    line<< "dcpRBF: control points " << r.nControl << " (+" << r.nAdded
        << " -" << r.nRemoved << ", guard +" << r.nGuard;
    if (r.waitEnded)
    {
        line<< ", wait ended";
    }
    if (r.nUndone)
    {
        line<< ", " << r.nUndone << " trial swap(s) undone";
    }
    if (r.trialPoints)
    {
        line<< ", trials at " << r.trialPoints << " points";
    }
    line<< (r.rescue ? ", rescue" : "") << "), quality min "
        << q.checkedMin << " mean " << q.checkedMean << " (" << q.nChecked
        << " cells checked";
    if (measured && q.nMeasured < q.nCells)
    {
        // qualityScan lowest: the region's cells measured exactly
        line<< ", " << q.nMeasured << " of " << q.nCells << " measured";
    }
    if (q.checkedInverted)
    {
        line<< ", " << q.checkedInverted << " inverted";
    }
    line<< "), relative boundary error " << r.boundaryError
        << (r.atMaxPoints ? " (at maxPoints)" : "");
    line<< ", time [ms] swap " << ms(t.swap).c_str()
        << " select " << ms(t.select).c_str()
        << " interpolate " << ms(t.interpolate).c_str()
        << " measure " << ms(t.measure).c_str()
        << " guard " << ms(t.guard).c_str()
        << " points " << ms(t.points).c_str();
    Info<< line.str().c_str() << endl;
}


void Foam::dcpRBFStepLog::writeRow
(
    const dcpRBFStepState& r,
    const dcpRBFQualityRegion::summary& q
)
{
    const times& t = times_;
    if (!file_.valid())
    {
        const fileName dir
        (
            time_.rootPath()/time_.globalCaseName()/"postProcessing"/"dcpRBF"
           /time_.timeName(time_.startTime().value())
        );
        mkDir(dir);
        file_.reset(new OFstream(dir/"dcpRBF.dat"));
        file_().precision(17);     // full precision, whatever writePrecision
        file_()
            << "# dcpRBF motion solver, one row per step" << nl
            << "# time nControl nAdded nRemoved nGuard nCells minQuality"
            << " meanQuality boundaryError atMaxPoints swapTime selectTime"
            << " interpolateTime guardTime nUndone pointsTime nInverted"
            << " measureTime" << endl;
    }
    file_()
        << time_.timeName() << ' ' << r.nControl << ' ' << r.nAdded << ' '
        << r.nRemoved << ' ' << r.nGuard << ' ' << q.nChecked << ' '
        << q.checkedMin << ' ' << q.checkedMean << ' ' << r.boundaryError
        << ' ' << label(r.atMaxPoints) << ' ' << t.swap << ' '
        << t.select << ' ' << t.interpolate << ' ' << t.guard
        << ' ' << r.nUndone << ' ' << t.points << ' ' << q.checkedInverted
        << ' ' << t.measure << endl;
}


void Foam::dcpRBFStepLog::write
(
    const dcpRBFStepState& r,
    const dcpRBFQualityRegion::summary* quality
)
{
    // the figures of no cell checked if the step measured none
    const dcpRBFQualityRegion::summary none;
    const dcpRBFQualityRegion::summary& q = quality ? *quality : none;
    writeInfo(r, q, quality);
    if (Pstream::master())
    {
        writeRow(r, q);
    }
}


// ************************************************************************* //
