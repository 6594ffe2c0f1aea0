/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFRotation, continued: the bodies and their centres from the
    settings.
\*---------------------------------------------------------------------------*/

#include "dcpRBFRotation.H"
#include "dcpRBFDictReader.H"
#include "syncTools.H"
#include "Time.H"

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::List<const Foam::dictionary*> Foam::dcpRBFRotation::bodyDictionaries
(
    const polyMesh& mesh,
    const dictionary& dict,
    const dcpRBFSettings& settings,
    List<labelList>& groups
)
{
    // without bodies: the moving patches, one body
    if (!dict.found("bodies"))
    {
        groups = List<labelList>(1, settings.movingPatchIDs());
        bodyNames_ = wordList(1, "movingPatches");
        return List<const dictionary*>(1, &dict);
    }
    if (!dict.findDict("bodies"))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword bodies must be a sub-dictionary of bodies, each"
            << " with patches and an optional centre, e.g. bodies { wing"
            << " { patches (wing); centre (0.25 0 0); } }"
            << exit(FatalIOError);
    }
    for (const word k : {"centre", "axis", "hingedTo"})
    {
        if (dict.found(k))
        {
            FatalIOErrorInFunction(dict)
                << "Keyword " << k << ": with bodies, each body has its own "
                << k << " (bodies { wing { patches (wing); centre (0.25 0 0);"
                << (k == "axis" ? " axis (0 1 0);" : "")
                << (k == "hingedTo" ? " hingedTo (mainWing);" : "") << " } }); remove "
                << k << " from rotation" << exit(FatalIOError);
        }
    }
    const dictionary& bodies = dict.subDict("bodies");
    List<const dictionary*> bodyDicts;
    for (const entry& e : bodies)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(bodies)
                << "Keyword bodies: entry " << e.keyword() << " is not a"
                << " dictionary { patches (...); centre (x y z); }"
                << exit(FatalIOError);
        }
        dcpRBFDictReader(e.dict()).checkKeywordsOf("bodies");
        groups.append
        (
            dcpRBFSettings::matchPatches
            (
                e.dict(), "patches",
                dcpRBFDictReader(e.dict()).getWordRes("patches", false),
                mesh.boundaryMesh()
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
    return bodyDicts;
}


Foam::labelList Foam::dcpRBFRotation::markBodies
(
    const polyMesh& mesh,
    const dictionary& dict,
    const dcpRBFSettings& settings,
    const List<labelList>& groups,
    const List<const dictionary*>& bodyDicts
) const
{
    // each moving patch in exactly one body
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
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
    for (const label patchi : settings.movingPatchIDs())
    {
        if (bodyOfPatch[patchi] < 0)
        {
            FatalIOErrorInFunction(dict)
                << "Keyword bodies: moving patch " << patches[patchi].name()
                << " is in no body. Allowed: every patch of movingPatches in"
                << " one body" << exit(FatalIOError);
        }
    }
    return mark;
}


void Foam::dcpRBFRotation::checkApart
(
    const polyMesh& mesh,
    const dictionary& dict,
    const List<labelList>& groups,
    const labelList& mark
) const
{
    // Bodies that touch (share points) cannot turn apart: one body
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    labelList lowest(mesh.nPoints(), labelMax);
    forAll(groups, b)
    {
        for (const label patchi : groups[b])
        {
            for (const label pointi : patches[patchi].meshPoints())
            {
                lowest[pointi] = min(lowest[pointi], b + 1);
            }
        }
    }
    syncTools::syncPointList(mesh, lowest, minEqOp<label>(), labelMax);
    const label nb = groups.size();
    label touching = -1;     // lower body x nb + higher body
    forAll(mark, pointi)
    {
        if (mark[pointi] > 0 && lowest[pointi] != mark[pointi])
        {
            touching = max(touching, (lowest[pointi] - 1)*nb + mark[pointi] - 1);
        }
    }
    reduce(touching, maxOp<label>());
    if (touching >= 0)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword bodies: bodies " << bodyNames_[touching/nb]
            << " and " << bodyNames_[touching % nb] << " share boundary"
            << " points: touching bodies cannot turn apart. Put their patches"
            << " in one body (its best-fit motion is blended, the relative"
            << " motion, e.g. a flap's deflection, is interpolated as the"
            << " non-rigid rest)" << exit(FatalIOError);
    }
}


void Foam::dcpRBFRotation::assignCandidates
(
    const labelList& mark,
    const label nBodies
)
{
    pointField marks(mark.size(), Zero);
    forAll(mark, pointi)
    {
        marks[pointi] = vector::one*scalar(mark[pointi]);
    }
    const dcprbf::Values global(boundary_.gather(marks));
    bodyOf_.assign(boundary_.size(), -1);
    bodyPoints_.assign(nBodies, {});
    for (label i = 0; i < boundary_.size(); ++i)
    {
        bodyOf_[i] = int(std::lround(global(i, 0))) - 1;
        if (bodyOf_[i] >= 0)
        {
            bodyPoints_[bodyOf_[i]].push_back(i);
        }
    }
}


Eigen::Vector3d Foam::dcpRBFRotation::centroid(const label b) const
{
    Eigen::Vector3d c(Eigen::Vector3d::Zero());
    for (const Eigen::Index i : bodyPoints_[b])
    {
        c += boundary_.points().row(i).transpose();
    }
    return c/double(bodyPoints_[b].size());
}


void Foam::dcpRBFRotation::readCentre(const label b, const dictionary& body)
{
    // given (mesh coordinates), or the centroid of the body's points
    if (bodyPoints_[b].empty())
    {
        FatalIOErrorInFunction(body)
            << "Body " << bodyNames_[b] << " has no boundary points"
            << exit(FatalIOError);
    }
    if (body.found("axis") && projection_.dim() != 3)
    {
        FatalIOErrorInFunction(body)
            << "Keyword axis is for 3D meshes: in 2D a body turns about the"
            << " plane's normal through centre. Remove axis" << exit(FatalIOError);
    }
    if (!body.found("centre"))
    {
        if (body.found("axis"))
        {
            FatalIOErrorInFunction(body)
                << "Keyword axis needs centre, a point of the axis (e.g. the"
                << " pivot: centre (0.25 0 0); axis (0 1 0);)"
                << exit(FatalIOError);
        }
        centres_[b] = centroid(b);
        return;
    }
    const dcpRBFDictReader r(body);
    projection_.toCore(r.getPoint("centre"), centres_[b].data());
    if (body.found("axis"))
    {
        levelWithCentroid(b, r.getDirection("axis"));
    }
    Eigen::Vector3d lo(Eigen::Vector3d::Constant(GREAT)), hi(-lo);
    for (const Eigen::Index i : bodyPoints_[b])
    {
        lo = lo.cwiseMin(boundary_.points().row(i).transpose());
        hi = hi.cwiseMax(boundary_.points().row(i).transpose());
    }
    const Eigen::Vector3d margin(0.1*(hi - lo).norm()*Eigen::Vector3d::Ones());
    if
    (
        (centres_[b].array() < (lo - margin).array()).any()
     || (centres_[b].array() > (hi + margin).array()).any()
    )
    {
        WarningInFunction
            << "Body " << bodyNames_[b] << ": centre "
            << projection_.pointFromCore(centres_[b].data()) << " is outside"
            << " the body's bounding box (" << projection_.pointFromCore(lo.data())
            << ' ' << projection_.pointFromCore(hi.data()) << "): the"
            << " blend turns everything within the body's farthest"
            << " point from the centre rigidly, a centre off the body"
            << " leaves less room for the twist. Is it the pivot?" << endl;
    }
}


void Foam::dcpRBFRotation::readBodies
(
    const polyMesh& mesh,
    const dictionary& dict,
    const dcpRBFSettings& settings
)
{
    List<labelList> groups;
    const List<const dictionary*> bodyDicts
    (
        bodyDictionaries(mesh, dict, settings, groups)
    );
    const labelList mark(markBodies(mesh, dict, settings, groups, bodyDicts));
    checkApart(mesh, dict, groups, mark);
    assignCandidates(mark, groups.size());
    centres_.resize(groups.size());
    axes_.assign(groups.size(), Eigen::Vector3d::Zero());
    axisChecked_.assign(groups.size(), false);
    partners_.assign(groups.size(), std::vector<bool>(boundary_.size(), false));
    forAll(groups, b)
    {
        readCentre(b, *bodyDicts[b]);
        readHinge(mesh, b, *bodyDicts[b], settings);
    }
}


void Foam::dcpRBFRotation::readHinge
(
    const polyMesh& mesh,
    const label b,
    const dictionary& body,
    const dcpRBFSettings& settings
)
{
    if (profile_ != blendProfile::hinge)
    {
        if (body.found("hingedTo"))
        {
            FatalIOErrorInFunction(body)
                << "Keyword hingedTo has no effect with blendProfile "
                << blendProfileNames[profile_] << ". It belongs to"
                << " blendProfile hinge" << exit(FatalIOError);
        }
        return;
    }
    if (projection_.dim() == 3 && axes_[b].isZero())
    {
        FatalIOErrorInFunction(body)
            << "blendProfile hinge: body " << bodyNames_[b] << " needs its"
            << " hinge line: centre (a point of it) and axis (its direction),"
            << " e.g. centre (0.75 0 0); axis (0 1 0);" << exit(FatalIOError);
    }
    if (!body.found("hingedTo"))
    {
        return;     // a hinge with a gap: nothing static next to the body
    }
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    labelList mark(mesh.nPoints(), 0);
    for
    (
        const label patchi
      : dcpRBFSettings::matchPatches
        (
            body, "hingedTo",
            dcpRBFDictReader(body).getWordRes("hingedTo", false), patches
        )
    )
    {
        if (settings.movingPatchIDs().found(patchi))
        {
            FatalIOErrorInFunction(body)
                << "Keyword hingedTo: patch " << patches[patchi].name()
                << " is in movingPatches. Allowed: the static or sliding"
                << " patches the body turns on (a flap's wing, the symmetry"
                << " plane at its root)" << exit(FatalIOError);
        }
        for (const label pointi : patches[patchi].meshPoints())
        {
            mark[pointi] = 1;
        }
    }
    syncTools::syncPointList(mesh, mark, maxEqOp<label>(), label(0));
    boolList onPartner(mark.size());
    forAll(mark, pointi)
    {
        onPartner[pointi] = mark[pointi] > 0;
    }
    partners_[b] = boundary_.gatherFlags(onPartner);
    for (label i = 0; i < boundary_.size(); ++i)
    {
        // (the points the body shares with them are the body's)
        partners_[b][i] = partners_[b][i] && bodyOf_[i] < 0;
    }
}


// ************************************************************************* //
