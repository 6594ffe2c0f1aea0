/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFRegion.H"
#include "dcpRBFDictReader.H"
#include "dcpRBFKeywords.H"
#include "cellSet.H"
#include "cyclicPolyPatch.H"
#include "cyclicAMIPolyPatch.H"
#include "processorPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The neighbour patch of a coupled patch whose two sides must move alike
//  (cyclic, cyclicAMI and those derived from them), -1 for any other
Foam::label neighbourPatch(const Foam::polyPatch& pp)
{
    if (Foam::isA<Foam::processorPolyPatch>(pp))
    {
        return -1;
    }
    if (const auto* c = Foam::isA<Foam::cyclicPolyPatch>(pp))
    {
        return c->neighbPatchID();
    }
    if (const auto* a = Foam::isA<Foam::cyclicAMIPolyPatch>(pp))
    {
        return a->neighbPatchID();
    }
    return -1;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::dcpRBFRegion::readCells
(
    const dictionary& coeffs,
    const dictionary& solverDict
)
{
    // (the solver dictionary's cellZone and cellSet are read by OpenFOAM's
    // zoneMotion too; dynamicMultiMotionSolverFvMesh puts a zone's there)
    word inCoeffs
    (
        dcpRBFDictReader(coeffs).getName
        (
            dcpRBFKeywords::get("dcpRBFCoeffs", "cellZone")
        )
    );
    if (inCoeffs.empty())
    {
        inCoeffs = "none";
    }
    const word zone(solverDict.getOrDefault<word>("cellZone", "none"));
    const word set(solverDict.getOrDefault<word>("cellSet", "none"));
    if (inCoeffs != "none" && zone != "none" && inCoeffs != zone)
    {
        FatalIOErrorInFunction(coeffs)
            << "Keyword cellZone: " << inCoeffs << " here, but the motion"
            << " solver's dictionary names cellZone " << zone << " (a zone of"
            << " dynamicMultiMotionSolverFvMesh, say). Allowed: one region;"
            << " remove one of them or make them the same" << exit(FatalIOError);
    }
    if (set != "none" && (inCoeffs != "none" || zone != "none"))
    {
        FatalIOErrorInFunction(solverDict)
            << "Keyword cellSet " << set << " with cellZone "
            << (inCoeffs != "none" ? inCoeffs : zone) << ": allowed one"
            << " region, a cellZone or a cellSet" << exit(FatalIOError);
    }
    if (set != "none")
    {
        source_ = "cellSet " + set;
        return cellSet(mesh_, set).sortedToc();
    }
    const word name(inCoeffs != "none" ? inCoeffs : zone);
    if (name == "none")
    {
        return labelList();
    }
    const label zonei = mesh_.cellZones().findZoneID(name);
    if (zonei < 0)
    {
        FatalIOErrorInFunction(inCoeffs != "none" ? coeffs : solverDict)
            << "Keyword cellZone: no cellZone " << name << " in the mesh."
            << " Allowed: " << mesh_.cellZones().names()
            << exit(FatalIOError);
    }
    source_ = "cellZone " + name;
    return mesh_.cellZones()[zonei];
}


void Foam::dcpRBFRegion::markPoints(const labelUList& cells)
{
    // the points of the region's cells, and of the others (labelLists:
    // GCC's alloc-size-larger-than on a boolList of nPoints)
    labelList in(mesh_.nPoints(), 0);
    labelList out(mesh_.nPoints(), 0);
    cells_.resize(mesh_.nCells());
    cells_.set(cells);
    const labelListList& cellPoints = mesh_.cellPoints();
    forAll(cellPoints, celli)
    {
        labelList& mark = cells_.test(celli) ? in : out;
        for (const label pointi : cellPoints[celli])
        {
            mark[pointi] = 1;
        }
    }
    syncTools::syncPointList(mesh_, in, maxEqOp<label>(), label(0));
    syncTools::syncPointList(mesh_, out, maxEqOp<label>(), label(0));
    points_.resize(mesh_.nPoints());
    border_.resize(mesh_.nPoints());
    shared_.resize(mesh_.nPoints());
    forAll(in, pointi)
    {
        points_.set(pointi, in[pointi] > 0);
        border_.set(pointi, in[pointi] > 0 && out[pointi] > 0);
        shared_.set(pointi, in[pointi] > 0 && out[pointi] > 0);
    }
}


Foam::labelList Foam::dcpRBFRegion::regionFaces() const
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    labelList n(patches.size(), 0);
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        // a cyclic's faces on another processor are a processorCyclic's
        label counted = patchi;
        if (const auto* pc = isA<processorCyclicPolyPatch>(pp))
        {
            counted = pc->referPatchID();
        }
        else if (isA<processorPolyPatch>(pp))
        {
            continue;
        }
        for (const label celli : pp.faceCells())
        {
            n[counted] += cell(celli);
        }
    }
    // (the processor patches, whose number differs between processors, last)
    for (label patchi = 0; patchi < patches.nNonProcessor(); ++patchi)
    {
        reduce(n[patchi], sumOp<label>());
    }
    return n;
}


void Foam::dcpRBFRegion::checkCoupled(const dictionary& coeffs)
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const labelList inRegion(regionFaces());
    labelList around(mesh_.nPoints(), 0);
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        const label neighbour = neighbourPatch(pp);
        if (neighbour < 0 || inRegion[patchi] == 0)
        {
            continue;
        }
        if (inRegion[neighbour] > 0)
        {
            FatalIOErrorInFunction(coeffs)
                << "Patch " << pp.name() << " is of type " << pp.type()
                << " and both its sides (" << pp.name() << ", "
                << patches[neighbour].name() << ") are in the region dcpRBF"
                << " moves (" << (whole() ? string("the whole mesh") : source_).c_str()
                << "): dcpRBF does not move the points of coupled patches"
                << " (cyclic, cyclicAMI, cyclicACMI, ...) consistently on both"
                << " sides. What works: a region on one side of a sliding"
                << " interface (cellZone in dcpRBFCoeffs, or dcpRBF as a"
                << " zone's solver of dynamicMultiMotionSolverFvMesh), whose"
                << " side of the interface then stays still in the region's"
                << " frame; or a mesh without coupled patches; or another"
                << " motion solver (solidBody for a rotating zone)"
                << exit(FatalIOError);
        }
        // around the region: its side of the interface is border
        for (const label pointi : pp.meshPoints())
        {
            around[pointi] = 1;
        }
    }
    syncTools::syncPointList(mesh_, around, maxEqOp<label>(), label(0));
    forAll(around, pointi)
    {
        if (around[pointi] > 0 && point(pointi))
        {
            border_.set(pointi);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFRegion::dcpRBFRegion
(
    const polyMesh& mesh,
    const dictionary& coeffs,
    const dictionary& solverDict
)
:
    mesh_(mesh)
{
    const labelList cells(readCells(coeffs, solverDict));
    if (!whole())
    {
        if (returnReduce(cells.size(), sumOp<label>()) == 0)
        {
            FatalIOErrorInFunction(coeffs)
                << "The region (" << source_.c_str() << ") has no cells:"
                << " nothing could move" << exit(FatalIOError);
        }
        markPoints(cells);
    }
    else
    {
        border_.resize(mesh_.nPoints());
        shared_.resize(mesh_.nPoints());
    }
    checkCoupled(coeffs);
    if (!whole())
    {
        Info<< "dcpRBF: region " << source_.c_str() << ": " << nCells()
            << " cells, " << nPoints() << " points, " << nBorder()
            << " of them on its border (static; " << nShared()
            << " shared with cells outside it, which stay where the mesh"
            << " has them)" << endl;
    }
}


Foam::dcpRBFRegion::dcpRBFRegion(const polyMesh& mesh)
:
    mesh_(mesh),
    border_(mesh.nPoints()),
    shared_(mesh.nPoints())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dcpRBFRegion::touches(const label patchi) const
{
    bool any = whole();
    for (const label pointi : mesh_.boundaryMesh()[patchi].meshPoints())
    {
        if (any) break;
        any = point(pointi);
    }
    return returnReduce(any, orOp<bool>());
}


Foam::label Foam::dcpRBFRegion::nCells() const
{
    return returnReduce(whole() ? mesh_.nCells() : label(cells_.count()), sumOp<label>());
}


Foam::label Foam::dcpRBFRegion::nPoints() const
{
    return returnReduce(whole() ? mesh_.nPoints() : label(points_.count()), sumOp<label>());
}


Foam::label Foam::dcpRBFRegion::nBorder() const
{
    return returnReduce(label(border_.count()), sumOp<label>());
}


Foam::label Foam::dcpRBFRegion::nShared() const
{
    return returnReduce(label(shared_.count()), sumOp<label>());
}


// ************************************************************************* //
