/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFSettings.H"
#include "dcpRBFDictReader.H"
#include "dcpRBFVersion.H"
#include "ThreadCount.hpp"
#include "emptyPolyPatch.H"
#include "processorPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "cyclicAMIPolyPatch.H"
#include "wordRes.H"
#include "pointFields.H"
#include "OStringStream.H"

#include <cctype>
#include <functional>
#include <limits>

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::Enum<Foam::dcpRBFSettings::floorAction>
Foam::dcpRBFSettings::floorActionNames
({
    {floorAction::warn, "warn"},
    {floorAction::stop, "stop"}
});

const Foam::Enum<dcprbf::TetQuality::Metric> Foam::dcpRBFSettings::metricNames
({
    {dcprbf::TetQuality::Metric::sizeShape, "sizeShape"},
    {dcprbf::TetQuality::Metric::size, "size"},
    {dcprbf::TetQuality::Metric::shape, "shape"}
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- A keyword of dcpRBFCoeffs
const Foam::dcpRBFKeyword& key(const char* name)
{
    return Foam::dcpRBFKeywords::get("dcpRBFCoeffs", name);
}

//- The choices of the keywords read into Enums, and of function: the
//  kernels' names
using choicesFrom = Foam::dcpRBFKeyword::choicesFrom;
const choicesFrom metricChoices
(
    "dcpRBFCoeffs", "qualityMetric", Foam::dcpRBFSettings::metricNames
);
const choicesFrom fvMeshMetricChoices
(
    "dcpRBFFvMeshCoeffs", "qualityMetric", Foam::dcpRBFSettings::metricNames
);
const choicesFrom floorActionChoices
(
    "dcpRBFCoeffs", "qualityFloorAction", Foam::dcpRBFSettings::floorActionNames
);
const choicesFrom functionChoices
(
    "dcpRBFCoeffs", "function",
    []()
    {
        return
            Foam::dcpRBFCompat::makeList<Foam::word>
            (
                dcprbf::RadialKernel::names()
            );
    }
);

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::dictionary& Foam::dcpRBFSettings::checkKeywords
(
    const dictionary& dict
)
{
    // Without a dcpRBFCoeffs sub-dictionary the motion solver is given the
    // whole dynamicMeshDict: say so, not "unknown keyword dynamicFvMesh"
    if (dict.found("motionSolver") || dict.found("solver") || dict.found("dynamicFvMesh"))
    {
        string near;
        for (const entry& e : dict)
        {
            // (in any case: dcpRbfCoeffs, DCPRBFCoeffs, ...)
            std::string lower(e.keyword());
            for (char& c : lower)
            {
                c = char(std::tolower(static_cast<unsigned char>(c)));
            }
            if
            (
                e.isDict() && lower.compare(0, 6, "dcprbf") == 0
             && lower != "dcprbffvmeshcoeffs"
            )
            {
                near = " (found " + e.keyword() + ": the name is dcpRBFCoeffs)";
            }
        }
        FatalIOErrorInFunction(dict)
            << "No dcpRBFCoeffs sub-dictionary in " << dict.name() << near.c_str()
            << ". The dcpRBF settings go in it, e.g." << nl
            << "    dcpRBFCoeffs" << nl << "    {" << nl
            << "        movingPatches (wing);" << nl
            << "        staticPatches (inlet outlet);" << nl
            << "        supportRadius 2.5;" << nl << "    }" << nl
            << exit(FatalIOError);
    }
    dcpRBFDictReader(dict).checkKeywordsOf("dcpRBFCoeffs");
    return dict;
}


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
          ? readPatches(dict, "movingPatches", mesh.boundaryMesh(), false)
          : readPatches(dict, "staticPatches", mesh.boundaryMesh(), true);
    }
    labelList movingIDs, staticIDs;
    inferPatches(dict, mesh, movingIDs, staticIDs, moving);
    return moving ? movingIDs : staticIDs;
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
    const pointVectorField* d =
        mesh.findObject<pointVectorField>("pointDisplacement");
    if (!d)
    {
        FatalIOErrorInFunction(dict)
            << "Keywords movingPatches and staticPatches missing, and no"
            << " pointDisplacement field to infer them from: give both,"
            << " e.g. movingPatches (wing); staticPatches (inlet outlet);"
            << exit(FatalIOError);
    }
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    DynamicList<label> moving, still;
    wordList sliding;
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        const pointPatchVectorField& pf = d->boundaryField()[patchi];
        if (pp.coupled() || polyPatch::constraintType(pp.type()))
        {
            continue;   // empty, wedge, symmetry, cyclic, processor, ...
        }
        if (!pf.fixesValue())
        {
            sliding.append(pp.name());
        }
        else if (pf.type() == "fixedValue")
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
    const auto names = [&patches](const labelList& ids)
    {
        wordList n(ids.size());
        forAll(ids, i)
        {
            n[i] = patches[ids[i]].name();
        }
        return n;
    };
    if (movingIDs.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Keywords movingPatches and staticPatches missing, and no"
            << " patch's pointDisplacement condition prescribes motion (fixed-"
            << "value kinds other than fixedValue: solidBodyMotionDisplacement,"
            << " angularOscillatingDisplacement, oscillatingDisplacement,"
            << " uniformFixedValue, ...). fixedValue patches "
            << names(staticIDs) << ", sliding " << sliding
            << ". Give movingPatches and staticPatches" << exit(FatalIOError);
    }
    if (!report)
    {
        return;
    }
    Info<< "dcpRBF: movingPatches " << names(movingIDs)
        << " and staticPatches " << names(staticIDs) << " from the"
        << " pointDisplacement conditions (fixedValue: static; another kind"
        << " that fixes the value: moving); ";
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


Foam::scalar Foam::dcpRBFSettings::movingExtent
(
    const polyMesh& mesh,
    const pointField& points0
) const
{
    // the moving patches' bounding box's diagonal, in the plane of a 2D
    // mesh (not the extrusion's thickness)
    boundBox bb(boundBox::invertedBox);
    for (const label patchi : movingPatchIDs_)
    {
        bb.add(points0, mesh.boundaryMesh()[patchi].meshPoints());
    }
    bb.reduce();
    vector span(bb.span());
    for (direction cmpt = 0; cmpt < vector::nComponents; ++cmpt)
    {
        if (mesh.geometricD()[cmpt] == -1) span[cmpt] = 0;
    }
    return mag(span);
}


Foam::scalar Foam::dcpRBFSettings::readRadius
(
    const dcpRBFDictReader& r,
    const polyMesh& mesh,
    const pointField& points0
) const
{
    // (within the table's bounds in units of the mesh's size)
    return
        r.getLength
        (
            key("supportRadius"), "movingExtent",
            [&]() { return movingExtent(mesh, points0); },
            mag(mesh.bounds().span())
        );
}


void Foam::dcpRBFSettings::readFarField
(
    const dcpRBFDictReader& r,
    const bool staticBorder
)
{
    const dcpRBFKeyword& k = key("farField");
    const bool given = r.dict().found(k.name);
    const bool still = given ? r.getChoice(k) == 0 : kernel_.compact();
    const bool rotation = r.getSwitch(key("rotationInterpolation"));
    if (given && still && rotation)
    {
        FatalIOErrorInFunction(r.dict())
            << "Keyword farField still has no effect with rotationInterpolation"
            << " true: the bodies' blend decides how far the motion reaches"
            << " (blendProfile, rotation { ... }). Allowed: farField"
            << " interpolated, or no farField" << exit(FatalIOError);
    }
    const bool staticPoints = staticPatchIDs_.size() || staticBorder;
    if (given && still && !staticPoints)
    {
        FatalIOErrorInFunction(r.dict())
            << "Keyword farField still has no effect without static points"
            << " (no staticPatches, no region border): the whole boundary"
            << " moves, and an affine motion of it is reproduced at every"
            << " point. Allowed: farField interpolated, or no farField, or"
            << " staticPatches (...)" << exit(FatalIOError);
    }
    stillFarField_ = still && !rotation && staticPoints;
}


dcprbf::RadialKernel Foam::dcpRBFSettings::readKernel
(
    const dcpRBFDictReader& r,
    const polyMesh& mesh,
    const pointField& points0
) const
{
    const dcpRBFKeyword& k = key("function");
    const word name(k.choiceList()[r.getChoice(k)]);
    return dcprbf::RadialKernel::fromName(name, readRadius(r, mesh, points0));
}


Foam::string Foam::dcpRBFSettings::changedEntries
(
    const dictionary& before,
    const dictionary& now
)
{
    // an entry on one line: its tokens, a sub-dictionary's entries in
    // braces; numbers to digits significant digits
    const std::function<string(const entry*, int)> text =
        [&](const entry* e, const int digits)
    {
        if (!e)
        {
            return string("(none)");
        }
        OStringStream os;
        os.precision(digits);
        if (e->isDict())
        {
            os << '{';
            for (const entry& sub : e->dict())
            {
                os << ' ' << sub.keyword() << ' ' << text(&sub, digits).c_str()
                   << (sub.isDict() ? "" : ";");
            }
            os << " }";
        }
        else
        {
            os << dcpRBFDictReader::asWritten(e->stream(), digits).c_str();
        }
        return string(os.str());
    };
    // compared at full precision, shown as a user writes them
    const int all = std::numeric_limits<double>::max_digits10;
    const int shown = 10;
    string changes;
    const auto add = [&](const string& key, const entry* was, const entry* is)
    {
        changes += (changes.empty() ? "" : ", ") + key + ' '
            + text(was, shown) + " -> " + text(is, shown);
    };
    const std::function<void(const dictionary&, const dictionary&, const string&)>
    compare = [&](const dictionary& a, const dictionary& b, const string& prefix)
    {
        for (const entry& e : b)
        {
            const entry* was = a.findEntry(e.keyword(), keyType::LITERAL);
            if (was && was->isDict() && e.isDict())
            {
                compare(was->dict(), e.dict(), prefix + e.keyword() + '/');
            }
            else if (text(was, all) != text(&e, all))
            {
                add(prefix + e.keyword(), was, &e);
            }
        }
        for (const entry& e : a)
        {
            if (!b.findEntry(e.keyword(), keyType::LITERAL))
            {
                add(prefix + e.keyword(), &e, nullptr);
            }
        }
    };
    compare(before, now, string());
    return changes;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFSettings::dcpRBFSettings
(
    const dictionary& dict,
    const polyMesh& mesh,
    const pointField& points0,
    const bool staticBorder
)
:
    movingPatchIDs_(patchList(checkKeywords(dict), mesh, true)),
    staticPatchIDs_(patchList(dict, mesh, false)),
    patchesInferred_(!dict.found("movingPatches") && !dict.found("staticPatches")),
    kernel_(readKernel(dcpRBFDictReader(dict), mesh, points0)),
    polynomial_(dcpRBFDictReader(dict).getSwitch(key("polynomial")))
{
    const dcpRBFDictReader r(dict);
    checkPatchLists(dict, mesh.boundaryMesh());

    if (kernel_.needsPolynomial() && !polynomial_)
    {
        FatalIOErrorInFunction(dict)
            << "function " << kernel_.name() << " needs polynomial true"
            << exit(FatalIOError);
    }

    if (dict.found("controlPoints"))
    {
        if (!dict.findDict("controlPoints"))
        {
            FatalIOErrorInFunction(dict)
                << "Keyword controlPoints must be a sub-dictionary,"
                << " e.g. controlPoints { selection dynamic; }"
                << exit(FatalIOError);
        }
        selection_ = dcpRBFSelectionSettings(dict.subDict("controlPoints"));
    }

    metric_ = r.getEnum(key("qualityMetric"), metricNames);
    scanLowest_ = r.getChoice(key("qualityScan")) == 1;
    qualityFloor_ = r.getScalar(key("qualityFloor"));
    floorAction_ = r.getEnum(key("qualityFloorAction"), floorActionNames);
    guardIterations_ = r.getLabel(key("guardIterations"));
    boundaryCorrection_ = r.getSwitch(key("boundaryCorrection"));
    readFarField(r, staticBorder);
    evaluationMemoryAuto_ = !dict.found("evaluationMemoryMB");
    evaluationMemoryMB_ = r.getLabel(key("evaluationMemoryMB"));
    pointsPerThread_ = r.getLabel(key("pointsPerThread"));
}


// ************************************************************************* //
