/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFStages.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFStages::dcpRBFStages
(
    const polyMesh& mesh,
    const dictionary& solverDict,
    const dictionary& coeffs,
    pointVectorField& pointDisplacement,
    const pointField& points0,
    const bool debug
)
:
    context_(mesh, solverDict, coeffs, pointDisplacement, points0, debug),
    controlPoints_(context_),
    rotation_(context_),
    quality_(context_, rotation_.active()),
    log_(context_.time(), quality_),
    writer_(context_.time(), context_.projection(), context_.boundaryPoints()),
    prescribed_(context_),
    interpolation_(context_, controlPoints_, rotation_, prescribed_),
    frame_(context_),
    cellDisplacement_(pointDisplacement),
    swapRule_
    (
        dcpRBFSwapRule::New(context_, controlPoints_, quality_, interpolation_)
    ),
    guard_(context_, controlPoints_, interpolation_, quality_)
{}


// ************************************************************************* //
