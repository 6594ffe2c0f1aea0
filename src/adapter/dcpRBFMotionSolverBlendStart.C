/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFMotionSolver, continued: the first step of a kept swaps' blend,
    checked against the mesh without the swaps.
\*---------------------------------------------------------------------------*/

#include "dcpRBFMotionSolver.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFMotionSolver::checkBlendStart
(
    const dcprbf::Values& d,
    dcpRBFStepLog::record& r
)
{
    // Swaps kept at the last step start their blend at this one; its mesh
    // is measured (lastQuality_). It must beat the mesh without the swaps
    // (the set the blend phases out, alone), as a trial step's written
    // mesh must: first bounded on the trials' window (the window's
    // minimum is at least the whole mesh's), else made and measured in
    // full. The same verdict either way (a restart, without the window,
    // takes the second; so does trialPoints all)
    const bool window =
        blendWindow_.valid()
     && blendWindowIndex_ == mesh().time().timeIndex() - 1
     && settings_.selection().trialAt == dcpRBFSelectionSettings::trialPoints::window;
    autoPtr<dcpRBFTrialWindow> w(std::move(blendWindow_));
    if (!controlPoints_.blending() || controlPoints_.blendStep() != 1)
    {
        return;
    }
    const auto report = [&]
    (
        const scalar blend, const scalar without, const char* where, const bool kept
    )
    {
        if (debug)
        {
            OStringStream msg;
            msg.precision(17);
            msg << typeName << ": blend start: minimum " << blend
                << " against " << without << " without the swaps (" << where
                << (kept ? "), kept" : "), given up");
            Info<< msg.str().c_str() << endl;
        }
    };
    controlPoints_.solveBlendOrigin(d);
    scalar error = 0;
    if (returnReduce(window, andOp<bool>()) && interpolateAt(d, w->points(), error))
    {
        const scalar bound = w->worst(trialPoints_)[0];
        if (lastQuality_.minQuality > bound)
        {
            report(lastQuality_.minQuality, bound, "window", true);
            controlPoints_.solveBlend(d);
            return;
        }
    }

    // In full: the blend's mesh kept aside
    const vectorField blendField(pointDisplacement_.primitiveField());
    dcpRBFQualityRegion::summary blendQuality(std::move(lastQuality_));
    pointField blendPoints(std::move(lastPoints_));
    const dcpRBFStepLog::record blendRecord(r);
    r.boundaryError = interpolateDisplacement(d);
    measureQuality(r);
    const bool keep = blendQuality.minQuality > lastQuality_.minQuality;
    report(blendQuality.minQuality, lastQuality_.minQuality, "in full", keep);
    if (keep)
    {
        pointDisplacement_.primitiveFieldRef() = blendField;
        lastQuality_ = std::move(blendQuality);
        lastPoints_.transfer(blendPoints);
        pointsMeasured_ = true;
        r = blendRecord;
        controlPoints_.solveBlend(d);
        return;
    }
    // without the swaps: that mesh is this step's
    r.nUndone += controlPoints_.abandonBlend();
}


// ************************************************************************* //
