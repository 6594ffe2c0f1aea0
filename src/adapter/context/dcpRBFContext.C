/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFContext.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFContext::dcpRBFContext
(
    const polyMesh& mesh,
    const dictionary& solverDict,
    const dictionary& coeffs,
    pointVectorField& pointDisplacement,
    const pointField& points0,
    const bool debug
)
:
    mesh_(mesh),
    coeffs_(dcpRBFSettings::coeffsIn(coeffs)),
    stepMesh_(pointDisplacement),
    points0_(points0),
    debug_(debug),
    region_(mesh, coeffs_, solverDict),
    settings_(coeffs_, mesh, points0, region_.nBorder() > 0),
    projection_(mesh),
    boundaryPoints_
    (
        mesh, projection_, settings_.movingPatchIDs(),
        settings_.staticPatchIDs(), points0, &region_
    ),
    evalPoints_(projection_.toCore(points0)),
    distinct_(evalPoints_),
    twoDPoints_(mesh)
{
    settings_.chooseDefaults(boundaryPoints_.size());
}


// ************************************************************************* //
