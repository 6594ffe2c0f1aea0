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
    region_(context.region()),
    normal_(Zero)
{
    if (mesh_.nSolutionD() == 2)
    {
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (mesh_.solutionD()[d] < 0) normal_[d] = 1;
        }
    }
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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFFrame::checkPlanar(const scalar across) const
{
    if (mesh_.nSolutionD() != 2)
    {
        return;
    }
    const scalar largest = returnReduce(across, maxOp<scalar>());
    if (largest > 1e-9*mag(mesh_.bounds().span()))
    {
        FatalErrorInFunction
            << "Keyword frame: at time " << mesh_.time().timeName()
            << " its solid-body motion moves the 2D mesh's points by up to "
            << largest << " across its plane (normal " << normal_ << "). On a"
            << " 2D mesh the frame may turn about the normal " << normal_
            << " and move within the plane only" << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFFrame::place(pointField& p) const
{
    if (motion_.valid())
    {
        // transformed once; in 2D the largest move across the plane too
        // (normal_ is zero in 3D)
        const septernion T(motion_->transformation());
        scalar across = 0;
        forAll(p, pointi)
        {
            const point q(T.transformPoint(p[pointi]));
            across = max(across, mag((q - p[pointi]) & normal_));
            p[pointi] = q;
        }
        checkPlanar(across);
    }
    const pointField& now = mesh_.points();
    for (const label pointi : outside_)
    {
        p[pointi] = now[pointi];
    }
}


// ************************************************************************* //
