/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFSettings, continued: the patch lists (movingPatches, staticPatches:
    read and checked, or inferred from the pointDisplacement conditions).
\*---------------------------------------------------------------------------*/

#include "dcpRBFSettings.H"
#include "dcpRBFDictReader.H"
#include "emptyPolyPatch.H"
#include "cyclicAMIPolyPatch.H"
#include "pointFields.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::dcpRBFSettings::patchList
(
    const dictionary& dict,
    const polyMesh& mesh,
    const bool moving
)
{
    if (dict.found("movingPatches") || dict.found("staticPatches"))
    {
        return moving
          ? readPatches(dict, "movingPatches", mesh.boundaryMesh(), dict.found("frame"))
          : readPatches(dict, "staticPatches", mesh.boundaryMesh(), true);
    }
    labelList movingIDs, staticIDs;
    inferPatches(dict, mesh, movingIDs, staticIDs, moving);
    return moving ? movingIDs : staticIDs;
}


Foam::wordList Foam::dcpRBFSettings::classifyPatches
(
    const polyBoundaryMesh& patches,
    const conditions& given,
    labelList& movingIDs,
    labelList& staticIDs
)
{
    DynamicList<label> moving, still;
    wordList sliding;
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        if (pp.coupled() || polyPatch::constraintType(pp.type()))
        {
            continue;   // empty, wedge, symmetry, cyclic, processor, ...
        }
        if (!given.fixes[patchi])
        {
            sliding.append(pp.name());
        }
        else if (!given.driven && given.types[patchi] == "fixedValue")
        {
            still.append(patchi);
        }
        else
        {
            moving.append(patchi);
        }
    }
    movingIDs = moving;
    staticIDs = still;
    return sliding;
}


Foam::dcpRBFSettings::conditions Foam::dcpRBFSettings::conditionsIn
(
    const polyMesh& mesh
)
{
    // the displacement's, else a driving field's (dcpRBFDrivenDisplacement:
    // a velocity, a component's velocity or displacement)
    if (const auto* d = mesh.findObject<pointVectorField>("pointDisplacement"))
    {
        return conditionsOf(*d, false);
    }
    if (const auto* u = mesh.findObject<pointVectorField>("pointMotionU"))
    {
        return conditionsOf(*u, true);
    }
    for (const word cmpt : {"x", "y", "z"})
    {
        for (const word field : {"pointMotionU" + cmpt, "pointDisplacement" + cmpt})
        {
            if (const auto* f = mesh.findObject<pointScalarField>(field))
            {
                return conditionsOf(*f, true);
            }
        }
    }
    return conditions();
}


void Foam::dcpRBFSettings::inferPatches
(
    const dictionary& dict,
    const polyMesh& mesh,
    labelList& movingIDs,
    labelList& staticIDs,
    const bool report
)
{
    // a driven case's (velocity, component): every fixed-value kind moving
    // (a mesh class may set a velocity while running)
    const conditions given(conditionsIn(mesh));
    if (given.name.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Keywords movingPatches and staticPatches missing, and no"
            << " pointDisplacement field to infer them from: give both,"
            << " e.g. movingPatches (wing); staticPatches (inlet outlet);"
            << exit(FatalIOError);
    }
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    const wordList sliding(classifyPatches(patches, given, movingIDs, staticIDs));
    const auto names = [&patches](const labelList& ids)
    {
        wordList n(ids.size());
        forAll(ids, i)
        {
            n[i] = patches[ids[i]].name();
        }
        return n;
    };
    if (movingIDs.empty() && !dict.found("frame"))
    {
        FatalIOErrorInFunction(dict)
            << "Keywords movingPatches and staticPatches missing, and no"
            << " patch's " << given.name << " condition prescribes motion ("
            << (
                   given.driven
                 ? "fixed-value kinds"
                 : "fixed-value kinds other than fixedValue:"
                   " solidBodyMotionDisplacement,"
                   " angularOscillatingDisplacement, oscillatingDisplacement,"
                   " uniformFixedValue, ..."
               )
            << "). fixedValue patches " << names(staticIDs)
            << ", sliding " << sliding
            << ". Give movingPatches and staticPatches" << exit(FatalIOError);
    }
    if (!report)
    {
        return;
    }
    Info<< "dcpRBF: movingPatches " << names(movingIDs)
        << " and staticPatches " << names(staticIDs) << " from the "
        << given.name << " conditions ("
        << (
               given.driven
             ? "every kind that fixes the value: moving); "
             : "fixedValue: static; another kind that fixes the value:"
               " moving); "
           );
    if (sliding.empty())
    {
        Info<< "no sliding patch";
    }
    else
    {
        Info<< "sliding " << sliding;
    }
    Info<< " (list both movingPatches and staticPatches to choose)" << endl;
}


Foam::labelList Foam::dcpRBFSettings::readPatches
(
    const dictionary& dict,
    const word& keyword,
    const polyBoundaryMesh& patches,
    const bool allowEmpty
)
{
    const wordRes matchers(dcpRBFDictReader(dict).getWordRes(keyword, allowEmpty));
    return matchPatches(dict, keyword, matchers, patches);
}


Foam::labelList Foam::dcpRBFSettings::matchPatches
(
    const dictionary& dict,
    const word& keyword,
    const wordRes& matchers,
    const polyBoundaryMesh& patches
)
{
    labelHashSet ids;
    for (const wordRe& m : matchers)
    {
        bool found = false;
        forAll(patches, patchi)
        {
            if (m.match(patches[patchi].name()))
            {
                ids.insert(patchi);
                found = true;
            }
        }
        forAllConstIters(patches.groupPatchIDs(), iter)
        {
            if (m.match(iter.key()))
            {
                ids.insert(iter.val());
                found = true;
            }
        }
        if (!found)
        {
            FatalIOErrorInFunction(dict)
                << "Keyword " << keyword << ": no patch or patch group matches "
                << m << ". Allowed patches: " << patches.names()
                << exit(FatalIOError);
        }
    }
    return ids.sortedToc();
}


void Foam::dcpRBFSettings::checkPatchLists
(
    const dictionary& dict,
    const polyBoundaryMesh& patches
) const
{
    for (const label patchi : movingPatchIDs_)
    {
        if (staticPatchIDs_.found(patchi))
        {
            FatalIOErrorInFunction(dict)
                << "Patch " << patches[patchi].name() << " is matched by both"
                << " movingPatches and staticPatches (by name, regular"
                << " expression or group): a patch either moves or stays put"
                << exit(FatalIOError);
        }
    }
    // (coupled patches in the region: refused by dcpRBFRegion)
    for (const word keyword : {"movingPatches", "staticPatches"})
    {
        const labelList& ids =
            keyword == "movingPatches" ? movingPatchIDs_ : staticPatchIDs_;
        for (const label patchi : ids)
        {
            const polyPatch& pp = patches[patchi];
            if (isA<emptyPolyPatch>(pp) || pp.coupled() || isA<cyclicAMIPolyPatch>(pp))
            {
                FatalIOErrorInFunction(dict)
                    << "Keyword " << keyword << ": patch " << pp.name()
                    << " is of type " << pp.type() << ". Allowed: wall,"
                    << " patch and other non-empty, non-coupled patches (a"
                    << " region's side of a sliding interface is static"
                    << " without being listed: cellZone)"
                    << exit(FatalIOError);
            }
        }
    }
}


// ************************************************************************* //
