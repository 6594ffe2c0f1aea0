/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
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
        << " -" << r.nRemoved << "), quality min " << r.minQuality
        << " mean " << r.meanQuality << " (" << r.nMovedCells
        << " moved cells), boundary error " << r.boundaryError
        << ", time select " << r.selectTime << " solve " << r.solveTime
        << " eval " << r.evalTime << " s" << endl;

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
            << "# time nControl nAdded nRemoved nMovedCells minQuality"
            << " meanQuality boundaryError selectTime solveTime evalTime"
            << endl;
    }
    file_()
        << time_.timeName() << ' ' << r.nControl << ' ' << r.nAdded << ' '
        << r.nRemoved << ' ' << r.nMovedCells << ' ' << r.minQuality << ' '
        << r.meanQuality << ' ' << r.boundaryError << ' ' << r.selectTime
        << ' ' << r.solveTime << ' ' << r.evalTime << endl;
}


// ************************************************************************* //
