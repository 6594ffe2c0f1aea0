/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFTwoDPoints.H"
#include "twoDPointCorrector.H"
#include "wedgePolyPatch.H"

#include <algorithm>
#include <vector>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFTwoDPoints::dcpRBFTwoDPoints(const polyMesh& mesh)
:
    mesh_(mesh),
    required_(twoDPointCorrector::New(mesh).required()),
    wedge_(false),
    pairsCoverPoints_(false),
    normal_(Zero)
{
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        wedge_ = wedge_ || isA<wedgePolyPatch>(pp);
    }
    if (!required_ || wedge_)
    {
        return;
    }
    const twoDPointCorrector& corrector = twoDPointCorrector::New(mesh);
    const labelList& normalEdges = corrector.normalEdgeIndices();
    const edgeList& edges = mesh.edges();
    pairs_.setSize(2*normalEdges.size());
    forAll(normalEdges, i)
    {
        pairs_[2*i] = edges[normalEdges[i]].start();
        pairs_[2*i + 1] = edges[normalEdges[i]].end();
    }
    // (std::vector: GCC's alloc-size-larger-than on a labelList of nPoints)
    std::vector<label> uses(std::size_t(mesh.nPoints()), 0);
    for (const label pointi : pairs_)
    {
        ++uses[pointi];
    }
    pairsCoverPoints_ =
        std::all_of(uses.begin(), uses.end(), [](label n) { return n == 1; });
    normal_ = corrector.planeNormal();
    const Vector<label>& dirs = mesh.geometricD();
    for (direction cmpt = 0; cmpt < vector::nComponents; ++cmpt)
    {
        empty_[cmpt] = dirs[cmpt] == -1;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class PointPair>
void Foam::dcpRBFTwoDPoints::correctPairs(const PointPair& pointPair) const
{
    // meshTools::constrainToMeshCentre's values, once
    const boundBox& bb = mesh_.bounds();
    scalar centre[vector::nComponents];
    for (direction cmpt = 0; cmpt < vector::nComponents; ++cmpt)
    {
        centre[cmpt] = 0.5*(bb.min()[cmpt] + bb.max()[cmpt]);
    }
    const bool* toCentre = empty_;
    const vector pn = normal_;
    const label* pair = pairs_.cdata();
    const label n = pairs_.size()/2;
    for (label i = 0; i < n; ++i)
    {
        point pStart, pEnd;
        point& start = pointPair(pair[2*i], pStart);
        point& end = pointPair(pair[2*i + 1], pEnd);
        point A = 0.5*(pStart + pEnd);
        for (direction cmpt = 0; cmpt < vector::nComponents; ++cmpt)
        {
            A[cmpt] = toCentre[cmpt] ? centre[cmpt] : A[cmpt];
        }
        start = A + pn*(pn & (pStart - A));
        end = A + pn*(pn & (pEnd - A));
    }
}


void Foam::dcpRBFTwoDPoints::correct(pointField& p) const
{
    if (!required_)
    {
        return;
    }
    if (wedge_)
    {
        twoDPointCorrector::New(mesh_).correctPoints(p);
        return;
    }
    correctPairs
    (
        [&p](const label pointi, point& value) -> point&
        {
            value = p[pointi];
            return p[pointi];
        }
    );
}


void Foam::dcpRBFTwoDPoints::move
(
    const pointField& p0,
    const vectorField& d,
    pointField& p
) const
{
    p.setSize(p0.size());
    if (required_ && !wedge_ && pairsCoverPoints_)
    {
        // every point is in one pair: made and corrected there
        correctPairs
        (
            [&](const label pointi, point& value) -> point&
            {
                value = p0[pointi] + d[pointi];
                return p[pointi];
            }
        );
        return;
    }
    forAll(p, pointi)
    {
        p[pointi] = p0[pointi] + d[pointi];
    }
    correct(p);
}


// ************************************************************************* //
