/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFFrame.H"
#include "Time.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFFrame::dcpRBFFrame(const dcpRBFContext& context)
:
    mesh_(context.mesh()),
    region_(context.region())
{
    const dictionary& coeffs = context.coeffs();
    if (coeffs.found("frame"))
    {
        if (!coeffs.findDict("frame"))
        {
            FatalIOErrorInFunction(coeffs)
                << "Keyword frame must be a sub-dictionary with a"
                << " solidBodyMotionFunction and its coefficients, e.g. frame"
                << " { solidBodyMotionFunction rotatingMotion;"
                << " rotatingMotionCoeffs { origin (0 0 0); axis (0 0 1);"
                << " omega 10; } }" << exit(FatalIOError);
        }
        motion_ = solidBodyMotionFunction::New
        (
            coeffs.subDict("frame"), mesh_.time()
        );
        if (region_.nShared() > 0)
        {
            FatalIOErrorInFunction(coeffs)
                << "Keyword frame: the region (" << region_.source().c_str()
                << ") shares " << region_.nShared() << " points with cells"
                << " outside it, which its solid-body motion would tear"
                << " from them. A region that moves as a solid body is"
                << " bounded by a sliding interface (cyclicAMI) or by its own"
                << " walls; or give the whole of the moving cells as its"
                << " cellZone" << exit(FatalIOError);
        }
    }
    // where the mesh has them: outside the region, and the border points
    // cells outside it share (another solver's, where one moves them)
    DynamicList<label> outside;
    for (label pointi = 0; pointi < mesh_.nPoints(); ++pointi)
    {
        if (!region_.point(pointi) || region_.shared(pointi))
        {
            outside.append(pointi);
        }
    }
    outside_.transfer(outside);
    places_ = moves() || returnReduce(outside_.size() > 0, orOp<bool>());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFFrame::place(pointField& p) const
{
    if (motion_.valid())
    {
        const septernion T(motion_->transformation());
        forAll(p, pointi)
        {
            p[pointi] = T.transformPoint(p[pointi]);
        }
    }
    const pointField& now = mesh_.points();
    for (const label pointi : outside_)
    {
        p[pointi] = now[pointi];
    }
}


// ************************************************************************* //
