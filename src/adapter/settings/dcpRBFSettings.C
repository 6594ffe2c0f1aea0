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

Foam::dictionary Foam::dcpRBFSettings::coeffsIn(const dictionary& dict)
{
    // Without a dcpRBFCoeffs sub-dictionary OpenFOAM's coeffDict() is the
    // motion solver's whole dictionary
    if (!dict.found("motionSolver") && !dict.found("solver") && !dict.found("dynamicFvMesh"))
    {
        return dict;
    }
    for (const entry& e : dict)
    {
        // a misspelt one (in any case: dcpRbfCoeffs, DCPRBFCoeffs, ...)
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
            FatalIOErrorInFunction(dict)
                << "Found " << e.keyword() << " in " << dict.name()
                << ": the name is dcpRBFCoeffs" << exit(FatalIOError);
        }
    }
    // dcpRBF's keywords outside it (cellZone is also the motion solver's)
    for (const word& name : dcpRBFKeywords::names("dcpRBFCoeffs"))
    {
        if (name != "cellZone" && dict.found(name))
        {
            FatalIOErrorInFunction(dict)
                << "Keyword " << name << " outside dcpRBFCoeffs in "
                << dict.name() << ": dcpRBF's settings go in it, e.g." << nl
                << "    dcpRBFCoeffs" << nl << "    {" << nl
                << "        " << name << " ...;" << nl << "    }" << nl
                << "(without dcpRBFCoeffs every setting is at its default)"
                << exit(FatalIOError);
        }
    }
    dictionary none;
    none.name() = dict.name() + ".dcpRBFCoeffs";
    return none;
}


const Foam::dictionary& Foam::dcpRBFSettings::checkKeywords
(
    const dictionary& dict
)
{
    dcpRBFDictReader(dict).checkKeywordsOf("dcpRBFCoeffs");
    return dict;
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
    return inPlane(mesh, bb);
}


Foam::scalar Foam::dcpRBFSettings::inPlane
(
    const polyMesh& mesh,
    const boundBox& bb
)
{
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
    // (within the table's bounds in units of the mesh's size; not given:
    // the reference mesh's extent, in the plane of a 2D or wedge mesh: the
    // same on a restart)
    return
        r.getLength
        (
            key("supportRadius"), "movingExtent",
            [&]() { return movingExtent(mesh, points0); },
            mag(mesh.bounds().span()), inPlane(mesh, boundBox(points0, true))
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
    radiusDefault_(!dict.found("supportRadius")),
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
