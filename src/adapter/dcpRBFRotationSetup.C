/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFRotation, continued: the bodies from the settings, and the blend
    weights (computed once, written as <startTime>/rotationBlend).
\*---------------------------------------------------------------------------*/

#include "dcpRBFRotation.H"
#include "dcpRBFDictReader.H"
#include "syncTools.H"
#include "pointFields.H"
#include "Time.H"
#include "clockTime.H"

#include <cmath>

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
        if (profile_ == blendProfile::star)
        {
            // 3D with many boundary points: radii from a 2-degree grid of
            // directions (decided on the global set: the same on every
            // processor); else exact at every point
            const int grid = (dim_ == 3 && boundary_.size() > 5000) ? 90 : 0;
            forAll(bodyNames_, b)
            {
                blend.setStar(b, slope_, ramp_, grid);
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
            << " bodies, blend computed in " << timer.elapsedTime() << " s"
            << nl;
        forAll(bodyNames_, b)
        {
            Info<< "    " << bodyNames_[b] << ": " << bodyPoints_[b].size()
                << " boundary points, centre "
                << projection_.pointFromCore(centres_[b].data())
                << ", farthest body point " << blend.innerRadius(b)
                << ", nearest static point " << blend.outerRadius(b)
                << " from it, blendProfile " << blendProfileNames[profile_]
                << nl;
        }
    }
    catch (const dcprbf::Error& e)
    {
        FatalIOErrorInFunction(dict)
            << "rotationInterpolation: " << e.what() << nl << "    Bodies "
            << bodyNames_ << exit(FatalIOError);
    }
}


// ************************************************************************* //
