/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
\*---------------------------------------------------------------------------*/

#include "dcpRBFSettings.H"
#include "dcpRBFVersion.H"
#include "emptyPolyPatch.H"
#include "wordRes.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::wordList Foam::dcpRBFSettings::selectionNames({"all"});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::dcpRBFSettings::readPatches
(
    const dictionary& dict,
    const word& keyword,
    const polyBoundaryMesh& patches,
    const bool allowEmpty
)
{
    const wordRes matchers(dict.get<wordRes>(keyword));
    if (matchers.empty() && !allowEmpty)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword " << keyword << " is an empty list. Allowed: patch"
            << " names, regular expressions or groups among "
            << patches.names() << exit(FatalIOError);
    }

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


void Foam::dcpRBFSettings::checkKeywords
(
    const dictionary& dict,
    const wordList& known
)
{
    for (const entry& e : dict)
    {
        if (!known.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown keyword " << e.keyword() << " in "
                << dict.dictName() << ". Allowed keywords: " << known
                << exit(FatalIOError);
        }
    }
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
                << "Patch " << patches[patchi].name() << " is named in both"
                << " movingPatches and staticPatches: a patch either moves"
                << " or stays put" << exit(FatalIOError);
        }
    }
    for (const word keyword : {"movingPatches", "staticPatches"})
    {
        const labelList& ids =
            keyword == "movingPatches" ? movingPatchIDs_ : staticPatchIDs_;
        for (const label patchi : ids)
        {
            const polyPatch& pp = patches[patchi];
            if (isA<emptyPolyPatch>(pp) || pp.coupled())
            {
                FatalIOErrorInFunction(dict)
                    << "Keyword " << keyword << ": patch " << pp.name()
                    << " is of type " << pp.type() << ". Allowed: wall,"
                    << " patch and other non-empty, non-coupled patches"
                    << exit(FatalIOError);
            }
        }
    }
}


bool Foam::dcpRBFSettings::readSwitch
(
    const dictionary& dict,
    const word& keyword,
    const bool deflt
)
{
    const entry* e = dict.findEntry(keyword, keyType::LITERAL);
    if (!e)
    {
        return deflt;
    }
    const token t(e->stream());
    const Switch sw
    (
        t.isWord() ? Switch(t.wordToken(), true) : Switch(Switch::INVALID)
    );
    if (!t.isWord() || !sw.valid())
    {
        FatalIOErrorInFunction(dict)
            << "Keyword " << keyword << " must be a switch; got " << t
            << ". Allowed values: true/false, on/off, yes/no"
            << exit(FatalIOError);
    }
    return bool(sw);
}


dcprbf::RadialKernel Foam::dcpRBFSettings::readKernel(const dictionary& dict)
{
    const word function(dict.getOrDefault<word>("function", "WendlandC2"));
    const auto& names = dcprbf::RadialKernel::names();
    if (std::find(names.begin(), names.end(), function) == names.end())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown function " << function << ". Allowed functions: "
            << wordList(names.begin(), names.end()) << exit(FatalIOError);
    }
    const scalar radius(dict.get<scalar>("supportRadius"));
    if (!(radius > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword supportRadius must be > 0 [m], got " << radius
            << exit(FatalIOError);
    }
    return dcprbf::RadialKernel::fromName(function, radius);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFSettings::dcpRBFSettings
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    movingPatchIDs_(readPatches(dict, "movingPatches", mesh.boundaryMesh(), false)),
    staticPatchIDs_(readPatches(dict, "staticPatches", mesh.boundaryMesh(), true)),
    kernel_(readKernel(dict)),
    polynomial_(readSwitch(dict, "polynomial", true)),
    selection_(selectionMode::all)
{
    checkKeywords
    (
        dict,
        {
            "movingPatches", "staticPatches", "function", "supportRadius",
            "polynomial", "controlPoints"
        }
    );
    checkPatchLists(dict, mesh.boundaryMesh());

    if (kernel_.needsPolynomial() && !polynomial_)
    {
        FatalIOErrorInFunction(dict)
            << "function " << kernel_.name() << " needs polynomial true"
            << exit(FatalIOError);
    }

    if (dict.found("controlPoints") && !dict.isDict("controlPoints"))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword controlPoints must be a sub-dictionary,"
            << " e.g. controlPoints { selection all; }" << exit(FatalIOError);
    }
    if (dict.isDict("controlPoints"))
    {
        const dictionary& cpDict = dict.subDict("controlPoints");
        checkKeywords(cpDict, {"selection"});
        const word sel(cpDict.getOrDefault<word>("selection", "all"));
        const label i = selectionNames.find(sel);
        if (i < 0)
        {
            FatalIOErrorInFunction(cpDict)
                << "Unknown selection " << sel << ". Allowed selections: "
                << selectionNames << exit(FatalIOError);
        }
        selection_ = selectionMode(i);
    }
}


// ************************************************************************* //
