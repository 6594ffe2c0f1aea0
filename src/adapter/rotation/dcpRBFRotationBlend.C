/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFRotation, continued: the blend weights (computed once, written as
    <startTime>/rotationBlend).
\*---------------------------------------------------------------------------*/

#include "dcpRBFRotation.H"
#include "pointFields.H"
#include "clockTime.H"
#include "StringStream.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFRotation::writeBlend(const polyMesh& mesh) const
{
    pointScalarField blend
    (
        IOobject
        (
            "rotationBlend",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        pointMesh::New(mesh),
        dimensionedScalar(dimless, Zero)
    );
    forAll(blend, pointi)
    {
        blend[pointi] = min(scalar(1), weights_.row(pointi).sum());
    }
    blend.write();
}


void Foam::dcpRBFRotation::setProfiles(dcprbf::BodyBlend& blend) const
{
    if (profile_ == blendProfile::log)
    {
        return;     // BodyBlend's own: the radial ring
    }
    // 3D with many boundary points: radii from a 2-degree grid of
    // directions (decided on the global set: the same on every processor);
    // else exact at every point
    const int grid = (projection_.dim() == 3 && boundary_.size() > 5000) ? 90 : 0;
    forAll(bodyNames_, b)
    {
        if (profile_ == blendProfile::hinge)
        {
            blend.setHinge(b, hingeAxis(b), partners_[b], slope_, ramp_, grid);
        }
        else
        {
            blend.setStar(b, slope_, ramp_, grid);
        }
    }
}


void Foam::dcpRBFRotation::reportBlend
(
    const dcprbf::BodyBlend& blend,
    const scalar seconds
) const
{
    Info<< "dcpRBF: rotationInterpolation, " << bodyNames_.size()
        << (bodyNames_.size() == 1 ? " body" : " bodies")
        << ", blend computed in " << seconds << " s" << nl;
    forAll(bodyNames_, b)
    {
        Info<< "    " << bodyNames_[b] << ": " << bodyPoints_[b].size()
            << " boundary points, centre "
            << projection_.pointFromCore(centres_[b].data())
            << ", farthest body point " << blend.innerRadius(b);
        if (std::isfinite(blend.outerRadius(b)))
        {
            Info<< ", nearest static point " << blend.outerRadius(b);
        }
        else
        {
            Info<< ", no static point (the whole mesh moves with it)";
        }
        Info<< " from it, blendProfile " << blendProfileNames[profile_];
        if (profile_ == blendProfile::hinge)
        {
            Info<< ", hinged to "
                << std::count(partners_[b].begin(), partners_[b].end(), true)
                << " static points (hingedTo: left out of the ring)";
        }
        Info<< nl;
    }
}


void Foam::dcpRBFRotation::computeWeights
(
    const polyMesh& mesh,
    const dictionary& dict
)
{
    clockTime timer;
    try
    {
        dcprbf::BodyBlend blend(boundary_.points(), bodyOf_, centres_);
        setProfiles(blend);
        weights_ = blend.weights(evalPoints_);
        if (profile_ == blendProfile::hinge)
        {
            boundaryWeights_ = blend.weights(boundary_.points());
        }
        writeBlend(mesh);
        reportBlend(blend, timer.elapsedTime());
    }
    catch (const dcprbf::Error& e)
    {
        OStringStream centres;
        for (const Eigen::Vector3d& c : centres_)
        {
            centres << projection_.pointFromCore(c.data()) << ' ';
        }
        FatalIOErrorInFunction(dict)
            << "rotationInterpolation: " << e.what() << nl << "    Bodies "
            << bodyNames_ << ", centres (keyword centre; moved along axis"
            << " where given) " << centres.str()
            << nl << "    A static point (or another body's) is closer to the"
            << " centre than the body in some direction: give the body's pivot"
            << " as its centre (keyword centre), inside or next to the body;"
            << " with axis, the centre moves along it level with the body's"
            << " centroid: check that the axis is the pivot's. A body that"
            << " turns on a static one along a shared hinge line (a flap):"
            << " blendProfile hinge, with axis and hingedTo"
            << exit(FatalIOError);
    }
}


// ************************************************************************* //
