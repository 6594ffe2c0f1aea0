/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFRotation.H"
#include "dcpRBFDictReader.H"
#include "syncTools.H"
#include "pointFields.H"
#include "Time.H"
#include "unitConversion.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::Enum<Foam::dcpRBFRotation::blendProfile>
Foam::dcpRBFRotation::blendProfileNames
({
    {blendProfile::star, "star"},
    {blendProfile::log, "log"},
    {blendProfile::cellSize, "cellSize"}
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFRotation::readBodies
(
    const polyMesh& mesh,
    const dictionary& dict,
    const dcpRBFSettings& settings
)
{
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    List<labelList> groups;
    List<const dictionary*> bodyDicts;
    if (dict.found("bodies"))
    {
        if (!dict.isDict("bodies") || dict.found("centre"))
        {
            FatalIOErrorInFunction(dict)
                << "Keyword bodies must be a sub-dictionary of bodies, each"
                << " with patches and an optional centre, e.g. bodies { wing"
                << " { patches (wing); centre (0.25 0 0); } }; then centre"
                << " belongs in each body" << exit(FatalIOError);
        }
        const dictionary& bodies = dict.subDict("bodies");
        for (const entry& e : bodies)
        {
            if (!e.isDict())
            {
                FatalIOErrorInFunction(bodies)
                    << "Keyword bodies: entry " << e.keyword() << " is not a"
                    << " dictionary { patches (...); centre (x y z); }"
                    << exit(FatalIOError);
            }
            dcpRBFDictReader(e.dict()).checkKeywords({"patches", "centre"});
            groups.append
            (
                dcpRBFSettings::matchPatches
                (
                    e.dict(), "patches", e.dict().get<wordRes>("patches"), patches
                )
            );
            bodyNames_.append(e.keyword());
            bodyDicts.append(&e.dict());
        }
        if (groups.empty())
        {
            FatalIOErrorInFunction(bodies)
                << "Keyword bodies is empty. Allowed: one sub-dictionary per"
                << " body, e.g. wing { patches (wing); }" << exit(FatalIOError);
        }
    }
    else
    {
        groups = List<labelList>(1, settings.movingPatchIDs());
        bodyNames_ = wordList(1, "movingPatches");
        bodyDicts = List<const dictionary*>(1, &dict);
    }

    // Mark the mesh points of each body (k + 1; 0: none)
    labelList mark(mesh.nPoints(), 0);
    labelList bodyOfPatch(patches.size(), -1);
    forAll(groups, b)
    {
        for (const label patchi : groups[b])
        {
            if (!settings.movingPatchIDs().found(patchi) || bodyOfPatch[patchi] >= 0)
            {
                FatalIOErrorInFunction(*bodyDicts[b])
                    << "Keyword patches: patch " << patches[patchi].name()
                    << (bodyOfPatch[patchi] >= 0 ? " is in two bodies" : " is not in movingPatches")
                    << ". Allowed: each patch of movingPatches in at most one body"
                    << exit(FatalIOError);
            }
            bodyOfPatch[patchi] = b;
            for (const label pointi : patches[patchi].meshPoints())
            {
                mark[pointi] = max(mark[pointi], b + 1);
            }
        }
    }
    syncTools::syncPointList(mesh, mark, maxEqOp<label>(), label(0));

    pointField marks(mesh.nPoints(), Zero);
    forAll(mark, pointi)
    {
        marks[pointi] = vector::one*scalar(mark[pointi]);
    }
    const dcprbf::Values global(boundary_.gather(marks));
    bodyOf_.assign(boundary_.size(), -1);
    bodyPoints_.assign(groups.size(), {});
    for (label i = 0; i < boundary_.size(); ++i)
    {
        bodyOf_[i] = int(std::lround(global(i, 0))) - 1;
        if (bodyOf_[i] >= 0)
        {
            bodyPoints_[bodyOf_[i]].push_back(i);
        }
    }

    // Centres: given (mesh coordinates), or the centroid of the body's points
    centres_.resize(groups.size());
    forAll(groups, b)
    {
        if (bodyPoints_[b].empty())
        {
            FatalIOErrorInFunction(*bodyDicts[b])
                << "Body " << bodyNames_[b] << " has no boundary points"
                << exit(FatalIOError);
        }
        if (bodyDicts[b]->found("centre"))
        {
            projection_.toCore(bodyDicts[b]->get<point>("centre"), centres_[b].data());
        }
        else
        {
            centres_[b].setZero();
            for (const Eigen::Index i : bodyPoints_[b])
            {
                centres_[b] += boundary_.points().row(i).transpose();
            }
            centres_[b] /= double(bodyPoints_[b].size());
        }
    }
}


std::vector<double> Foam::dcpRBFRotation::cellExtents
(
    const polyMesh& mesh,
    const Eigen::Vector3d& centre,
    const scalar inner,
    const scalar outer
) const
{
    scalarList h(nProfileBins_, scalar(0));
    const scalar dr = (outer - inner)/nProfileBins_;
    const labelListList& cellPoints = mesh.cellPoints();
    forAll(cellPoints, celli)
    {
        scalar rMin = GREAT, rMax = -GREAT;
        for (const label pointi : cellPoints[celli])
        {
            const scalar r = (evalPoints_.row(pointi).transpose() - centre).norm();
            rMin = min(rMin, r);
            rMax = max(rMax, r);
        }
        if (rMax <= inner || rMin >= outer)
        {
            continue;
        }
        const label k0 = max(label(0), label((rMin - inner)/dr));
        const label k1 = min(nProfileBins_ - 1, label((rMax - inner)/dr));
        for (label k = k0; k <= k1; ++k)
        {
            h[k] = max(h[k], rMax - rMin);
        }
    }
    Pstream::listCombineGather(h, maxEqOp<scalar>());
    Pstream::listCombineScatter(h);
    return std::vector<double>(h.begin(), h.end());
}


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


void Foam::dcpRBFRotation::readState()
{
    motions_.assign(bodyNames_.size(), dcprbf::RigidMotion());
    if (!state_->found("rotations"))
    {
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

Foam::dcpRBFRotation::dcpRBFRotation
(
    const polyMesh& mesh,
    const dictionary& coeffs,
    const dcpRBFSettings& settings,
    const dcpRBFBoundaryPoints& boundary,
    const dcpRBFPlaneProjection& projection,
    const dcprbf::Points& evalPoints
)
:
    active_(dcpRBFDictReader(coeffs).getSwitch("rotationInterpolation", false)),
    dim_(projection.dim()),
    projection_(projection),
    boundary_(boundary),
    evalPoints_(evalPoints)
{
    if (coeffs.found("rotation") && !coeffs.isDict("rotation"))
    {
        FatalIOErrorInFunction(coeffs)
            << "Keyword rotation must be a sub-dictionary, e.g."
            << " rotation { bodies ((wing)); }" << exit(FatalIOError);
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
    r.checkKeywords({"bodies", "centre", "blendProfile", "blendSlope", "blendRamp"});
    readBodies(mesh, dict, settings);
    profile_ = r.getEnum("blendProfile", blendProfileNames, blendProfile::star);
    slope_ = r.getScalar("blendSlope", 0.25, -SMALL, 10);
    ramp_ = r.getScalar("blendRamp", 0.1, -SMALL, 1);
    if (profile_ != blendProfile::star)
    {
        for (const word k : {"blendSlope", "blendRamp"})
        {
            if (dict.found(k))
            {
                FatalIOErrorInFunction(dict)
                    << "Keyword " << k << " has no effect with blendProfile "
                    << blendProfileNames[profile_] << ". It belongs to"
                    << " blendProfile star" << exit(FatalIOError);
            }
        }
    }

    state_.reset
    (
        new IOdictionary
        (
            IOobject
            (
                "dcpRBFRotationState",
                mesh.time().timeName(),
                "uniform",
                mesh,
                IOobject::READ_IF_PRESENT,
                IOobject::AUTO_WRITE
            )
        )
    );
    readState();

    try
    {
        dcprbf::BodyBlend blend(boundary_.points(), bodyOf_, centres_);
        if (profile_ == blendProfile::star)
        {
            forAll(bodyNames_, b)
            {
                blend.setStar(b, slope_, ramp_);
            }
        }
        else if (profile_ == blendProfile::cellSize)
        {
            forAll(bodyNames_, b)
            {
                if (std::isfinite(blend.outerRadius(b)))
                {
                    blend.setDensity
                    (
                        b,
                        dcprbf::BodyBlend::cellAdaptedDensity
                        (
                            cellExtents
                            (
                                mesh, centres_[b], blend.innerRadius(b),
                                blend.outerRadius(b)
                            )
                        )
                    );
                }
            }
        }
        weights_ = blend.weights(evalPoints_);
        writeBlend(mesh);
        Info<< "dcpRBF: rotationInterpolation, " << bodyNames_.size()
            << " bodies" << nl;
        forAll(bodyNames_, b)
        {
            Info<< "    " << bodyNames_[b] << ": " << bodyPoints_[b].size()
                << " boundary points, blendProfile "
                << blendProfileNames[profile_] << ", centre "
                << projection_.pointFromCore(centres_[b].data())
                << ", turns rigidly within " << blend.innerRadius(b)
                << ", blend ends at " << blend.outerRadius(b) << nl;
        }
    }
    catch (const dcprbf::Error& e)
    {
        FatalIOErrorInFunction(dict)
            << "rotationInterpolation: " << e.what() << nl << "    Bodies "
            << bodyNames_ << exit(FatalIOError);
    }
    displacement_.setZero(evalPoints_.rows(), 3);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

dcprbf::Values Foam::dcpRBFRotation::fit(const dcprbf::Values& d)
{
    const dcprbf::Points& x = boundary_.points();
    List<vector> rotations(bodyNames_.size());
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
        motions_[b] =
            dcprbf::fitRigidMotion(xb, db, dim_, motions_[b].rotation)
           .about(centres_[b]);
        const Eigen::Vector3d& w = motions_[b].rotation;
        rotations[b] = vector(w.x(), w.y(), w.z());
    }
    state_->set("bodies", bodyNames_);
    state_->set("rotations", rotations);

    // The rest: prescribed minus each body's rigid motion
    dcprbf::Values rest(d);
    for (label i = 0; i < boundary_.size(); ++i)
    {
        if (bodyOf_[i] >= 0)
        {
            rest.row(i) -=
                motions_[bodyOf_[i]].displacement(x.row(i).transpose()).transpose();
        }
    }
    const scalar scale = d.rows() ? d.cwiseAbs().maxCoeff() : 0;
    if (rest.rows() && rest.cwiseAbs().maxCoeff() <= 1e-9*scale)
    {
        rest.setZero();
    }

    dcprbf::blendedRigidDisplacement(motions_, evalPoints_, weights_, displacement_);
    return rest;
}


void Foam::dcpRBFRotation::report(Ostream& os) const
{
    forAll(bodyNames_, b)
    {
        const dcprbf::RigidMotion& m = motions_[b];
        const scalar angle = dim_ == 2 ? m.rotation.z() : m.rotation.norm();
        os  << "    body " << bodyNames_[b] << ": rotation " << radToDeg(angle)
            << " deg";
        if (dim_ == 3 && angle > 0)
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
