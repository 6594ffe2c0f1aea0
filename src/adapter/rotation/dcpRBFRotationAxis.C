/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFRotation, continued: a 3D body's pivot axis (keyword axis): the
    centre placed on it, the check that the body turns about it, and the
    hint to give it.
\*---------------------------------------------------------------------------*/

#include "dcpRBFRotation.H"
#include "unitConversion.H"

#include <Eigen/Geometry>

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Eigen::Vector3d Foam::dcpRBFRotation::levelPoint
(
    const label b,
    const Eigen::Vector3d& e
) const
{
    return centres_[b] + e*e.dot(centroid(b) - centres_[b]);
}


double Foam::dcpRBFRotation::farthest(const label b, const Eigen::Vector3d& c) const
{
    double r = 0;
    for (const Eigen::Index i : bodyPoints_[b])
    {
        r = std::max(r, (boundary_.points().row(i).transpose() - c).norm());
    }
    return r;
}


void Foam::dcpRBFRotation::levelWithCentroid(const label b, const vector& axis)
{
    // the same rotations about the axis; the blend's centre level with the
    // body's middle, where its farthest point is nearer than at an end (a
    // wing pitching about its span axis: near mid-span, not the root)
    Eigen::Vector3d& e = axes_[b];
    projection_.toCore(axis, e.data());
    const point given(projection_.pointFromCore(centres_[b].data()));
    centres_[b] = levelPoint(b, e);
    Info<< "dcpRBF: rotationInterpolation: body " << bodyNames_[b] << ": centre "
        << given << " moved along its axis (unit " << axis << ") to "
        << projection_.pointFromCore(centres_[b].data())
        << ", level with the centroid of the body's points" << endl;
}


void Foam::dcpRBFRotation::checkAxis(const label b)
{
    // 3D, past 1 deg: the axis placed the centre, and a body turning about
    // another axis (10 deg off) has its centre off the pivot (warned once);
    // without an axis, at the first such step, a hint when one would help
    const Eigen::Vector3d& w = motions_[b].rotation;
    if (axisChecked_[b] || projection_.dim() != 3 || w.norm() < degToRad(1.0))
    {
        return;
    }
    const Eigen::Vector3d& e = axes_[b];
    if (e.isZero())
    {
        axisChecked_[b] = true;
        hintAxis(b);
        return;
    }
    const scalar off = radToDeg(std::atan2(w.cross(e).norm(), std::abs(w.dot(e))));
    if (off > 10)
    {
        axisChecked_[b] = true;
        const Eigen::Vector3d u(w.normalized());
        WarningInFunction
            << "Body " << bodyNames_[b] << " turns about "
            << projection_.fromCore(u.data()) << ", " << off << " deg off its"
            << " keyword axis " << projection_.fromCore(e.data()) << ": the"
            << " centre was moved along that axis, off the pivot, and the"
            << " translation about it is interpolated with the rest. Give the"
            << " axis the body turns about, or remove axis (warned once)" << endl;
    }
}


void Foam::dcpRBFRotation::hintAxis(const label b)
{
    // a rotation about the centre (no translation), about an axis on which
    // another point leaves the body's farthest point 10 % nearer
    const dcprbf::RigidMotion& m = motions_[b];
    const double rIn = farthest(b, centres_[b]);
    if (m.translation.norm() > 1e-6*rIn*m.rotation.norm())
    {
        return;
    }
    const Eigen::Vector3d u(m.rotation.normalized());
    const Eigen::Vector3d c(levelPoint(b, u));
    const double rLevel = farthest(b, c);
    if (rLevel < 0.9*rIn)
    {
        // as a user would write them: round-off (below 1e-9) dropped
        const auto rounded = [](vector v, const scalar scale)
        {
            for (direction k = 0; k < vector::nComponents; ++k)
            {
                if (mag(v[k]) < 1e-9*scale) v[k] = 0;
            }
            return v;
        };
        const vector axis(rounded(projection_.fromCore(u.data()), 1));
        Info<< "dcpRBF: rotationInterpolation: body " << bodyNames_[b]
            << " turns about " << axis << " through its centre. Hint: axis "
            << axis << " in its rotation dictionary would centre the blend"
            << " at " << rounded(projection_.pointFromCore(c.data()), rIn)
            << ", level with its"
            << " centroid, where its farthest point is " << rLevel << " away"
            << " instead of " << rIn << ": more room for the twist"
            << " (docs/guides/rotation.md)" << endl;
    }
}


// ************************************************************************* //
