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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFFrame::checkPlanar(const septernion& T, const pointField& p) const
{
    if (mesh_.nSolutionD() != 2)
    {
        return;
    }
    const Vector<label>& solved = mesh_.solutionD();
    vector normal(Zero);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solved[d] < 0) normal[d] = 1;
    }
    scalar across = 0;
    forAll(p, pointi)
    {
        across = max(across, mag((T.transformPoint(p[pointi]) - p[pointi]) & normal));
    }
    reduce(across, maxOp<scalar>());
    if (across > 1e-9*mag(mesh_.bounds().span()))
    {
        FatalErrorInFunction
            << "Keyword frame: at time " << mesh_.time().timeName()
            << " its solid-body motion moves the 2D mesh's points by up to "
            << across << " across its plane (normal " << normal << "). On a"
            << " 2D mesh the frame may turn about the normal " << normal
            << " and move within the plane only" << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFFrame::place(pointField& p) const
{
    if (motion_.valid())
    {
        const septernion T(motion_->transformation());
        checkPlanar(T, p);
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
