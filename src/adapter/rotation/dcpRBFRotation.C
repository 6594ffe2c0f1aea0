/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFRotation.H"
#include "dcpRBFDictReader.H"
#include "Time.H"
#include "unitConversion.H"
#include "mathematicalConstants.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::Enum<Foam::dcpRBFRotation::blendProfile>
Foam::dcpRBFRotation::blendProfileNames
({
    {blendProfile::star, "star"},
    {blendProfile::log, "log"},
    {blendProfile::hinge, "hinge"}
});

//- The choices of blendProfile: the Enum's names
static const Foam::dcpRBFKeyword::choicesFrom blendProfileChoices
(
    "rotation", "blendProfile", Foam::dcpRBFRotation::blendProfileNames
);


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFRotation::storeState(dictionary& state) const
{
    List<vector> rotations(motions_.size());
    forAll(rotations, b)
    {
        const Eigen::Vector3d& w = motions_[b].rotation;
        rotations[b] = vector(w.x(), w.y(), w.z());
    }
    state.set("bodies", bodyNames_);
    state.set("rotations", rotations);
}


void Foam::dcpRBFRotation::readState()
{
    motions_.assign(bodyNames_.size(), dcprbf::RigidMotion());
    if (!state_->found("rotations"))
    {
        if (state_->time().value() != 0)
        {
            WarningInFunction
                << "No rotation state " << state_->objectPath() << ": the"
                << " bodies' angles start from the rotation that takes points0"
                << " to the first step's boundary the short way (within 180"
                << " deg). A body turned further since points0 would be turned"
                << " back the other way: restart from a time written with"
                << " rotationInterpolation on" << endl;
        }
        return;
    }
    const List<vector> rotations(state_->get<List<vector>>("rotations"));
    if (rotations.size() != bodyNames_.size())
    {
        FatalIOErrorInFunction(*state_)
            << "rotations: " << rotations.size() << " bodies, the settings"
            << " have " << bodyNames_.size() << " " << bodyNames_
            << ": the state does not match dcpRBFCoeffs" << exit(FatalIOError);
    }
    forAll(rotations, b)
    {
        motions_[b].rotation = Eigen::Vector3d(rotations[b].x(), rotations[b].y(), rotations[b].z());
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFRotation::dcpRBFRotation(const dcpRBFContext& context)
:
    active_
    (
        dcpRBFDictReader(context.coeffs()).getSwitch
        (
            dcpRBFKeywords::get("dcpRBFCoeffs", "rotationInterpolation")
        )
    ),
    projection_(context.projection()),
    boundary_(context.boundaryPoints()),
    evalPoints_(context.evalPoints())
{
    const polyMesh& mesh = context.mesh();
    const dictionary& coeffs = context.coeffs();
    const dcpRBFSettings& settings = context.settings();
    if (coeffs.found("rotation") && !coeffs.findDict("rotation"))
    {
        FatalIOErrorInFunction(coeffs)
            << "Keyword rotation must be a sub-dictionary, e.g."
            << " rotation { centre (0.25 0 0); }" << exit(FatalIOError);
    }
    if (!active_)
    {
        if (coeffs.found("rotation"))
        {
            FatalIOErrorInFunction(coeffs)
                << "Keyword rotation has no effect with rotationInterpolation"
                << " false. Allowed: rotationInterpolation true"
                << exit(FatalIOError);
        }
        return;
    }
    const dictionary& dict =
        coeffs.found("rotation") ? coeffs.subDict("rotation") : dictionary::null;
    const dcpRBFDictReader r(dict);
    r.checkKeywordsOf("rotation");
    profile_ = r.getEnum(dcpRBFKeywords::get("rotation", "blendProfile"), blendProfileNames);
    readBodies(mesh, dict, settings);
    slope_ = r.getScalar(dcpRBFKeywords::get("rotation", "blendSlope"));
    ramp_ = r.getScalar(dcpRBFKeywords::get("rotation", "blendRamp"));
    if (profile_ == blendProfile::log)
    {
        for (const word k : {"blendSlope", "blendRamp"})
        {
            if (dict.found(k))
            {
                FatalIOErrorInFunction(dict)
                    << "Keyword " << k << " has no effect with blendProfile "
                    << blendProfileNames[profile_] << ". It belongs to"
                    << " blendProfile star or hinge" << exit(FatalIOError);
            }
        }
    }

    state_.reset
    (
        new dcpRBFStateDictionary
        (
            "dcpRBFRotationState", mesh,
            [this](dictionary& state) { storeState(state); }
        )
    );
    readState();

    computeWeights(mesh, dict);
    displacement_.setZero(evalPoints_.rows(), 3);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

dcprbf::Values Foam::dcpRBFRotation::fit(const dcprbf::Values& d)
{
    const dcprbf::Points& x = boundary_.points();
    std::vector<dcprbf::RigidMotion> turns(bodyNames_.size());
    forAll(bodyNames_, b)
    {
        const std::vector<Eigen::Index>& idx = bodyPoints_[b];
        dcprbf::Points xb(idx.size(), 3);
        dcprbf::Values db(idx.size(), 3);
        for (std::size_t k = 0; k < idx.size(); ++k)
        {
            xb.row(k) = x.row(idx[k]);
            db.row(k) = d.row(idx[k]);
        }
        const Eigen::Vector3d last(motions_[b].rotation);
        motions_[b] =
            dcprbf::fitRigidMotion(xb, db, projection_.dim(), last)
           .about(centres_[b]);
        const Eigen::Vector3d& w = motions_[b].rotation;
        if ((w - last).norm() > 0.5*constant::mathematical::pi)
        {
            WarningInFunction
                << "Body " << bodyNames_[b] << " turned by "
                << radToDeg((w - last).norm()) << " deg in one step: the angle"
                << " is only known modulo 360 deg from the last step's (and"
                << " from zero without " << state_->objectPath() << ")"
                << endl;
        }

        checkAxis(b);

        // the blended part: the rotation about the centre; the translation
        // is interpolated with the rest
        turns[b] = motions_[b];
        turns[b].translation.setZero();
        if (profile_ == blendProfile::hinge)
        {
            // a hinge turns about its line: the fit's part off the axis
            // (a round-off tilt, or the strip's) is interpolated with the rest
            const Eigen::Vector3d e(hingeAxis(b));
            turns[b].rotation = e*e.dot(turns[b].rotation);
        }
    }

    // The rest: prescribed minus each body's rotation about its centre
    // (its translation and its non-rigid motion); hinged, minus the
    // blended rotation, which is not the body's near the hinge line nor 0
    // on the partner
    dcprbf::Values rest(d);
    if (profile_ == blendProfile::hinge)
    {
        dcprbf::Values blended;
        dcprbf::blendedRigidDisplacement(turns, x, boundaryWeights_, blended);
        rest -= blended;
    }
    else
    {
        for (label i = 0; i < boundary_.size(); ++i)
        {
            if (bodyOf_[i] >= 0)
            {
                rest.row(i) -=
                    turns[bodyOf_[i]].displacement(x.row(i).transpose()).transpose();
            }
        }
    }
    const scalar scale = d.rows() ? d.cwiseAbs().maxCoeff() : 0;
    if (rest.rows() && rest.cwiseAbs().maxCoeff() <= 1e-9*scale)
    {
        rest.setZero();
    }

    dcprbf::blendedRigidDisplacement(turns, evalPoints_, weights_, displacement_);
    return rest;
}


void Foam::dcpRBFRotation::report(Ostream& os) const
{
    forAll(bodyNames_, b)
    {
        const dcprbf::RigidMotion& m = motions_[b];
        const scalar angle = projection_.dim() == 2 ? m.rotation.z() : m.rotation.norm();
        os  << "    body " << bodyNames_[b] << ": rotation " << radToDeg(angle)
            << " deg";
        if (projection_.dim() == 3 && angle > 0)
        {
            const Eigen::Vector3d a(m.rotation/angle + Eigen::Vector3d::Zero());  // no -0
            os  << " about (" << a.x() << ' ' << a.y() << ' ' << a.z() << ')';
        }
        os  << ", translation (" << m.translation.x() << ' '
            << m.translation.y() << ' ' << m.translation.z()
            << "), rms non-rigid " << m.rmsResidual << nl;
    }
}


// ************************************************************************* //
