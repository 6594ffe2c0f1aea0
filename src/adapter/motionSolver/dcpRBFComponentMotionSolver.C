/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFComponentMotionSolver.H"
#include "valuePointPatchField.H"
#include "pointFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dcpRBFComponentMotionSolver, 0);
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::word Foam::dcpRBFComponentMotionSolver::fieldName
(
    const polyMesh& mesh,
    const dictionary& dict
)
{
    // the component at the top level or in the former solver's
    // coefficients (displacementComponentLaplacianCoeffs)
    word cmpt(dict.getOrDefault<word>("component", word::null));
    for (const entry& e : dict)
    {
        if
        (
            cmpt.empty() && e.isDict()
         && e.keyword().ends_with("ComponentLaplacianCoeffs")
        )
        {
            cmpt = e.dict().getOrDefault<word>("component", word::null);
        }
    }
    if (cmpt != "x" && cmpt != "y" && cmpt != "z")
    {
        return word::null;
    }
    for (const word name : {"pointMotionU" + cmpt, "pointDisplacement" + cmpt})
    {
        if (dcpRBFMotionSolver::inTime<scalar>(mesh, name))
        {
            return name;
        }
    }
    return word::null;
}


bool Foam::dcpRBFComponentMotionSolver::drives
(
    const polyMesh& mesh,
    const dictionary& dict
)
{
    return
        !dcpRBFMotionSolver::inTime<vector>(mesh, "pointDisplacement")
     && !dcpRBFMotionSolver::inTime<vector>(mesh, "pointMotionU")
     && fieldName(mesh, dict).size();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFComponentMotionSolver::dcpRBFComponentMotionSolver
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    dcpRBFComponentMotionSolver(mesh, dict, fieldName(mesh, dict))
{}


Foam::dcpRBFComponentMotionSolver::dcpRBFComponentMotionSolver
(
    const polyMesh& mesh,
    const IOdictionary& dict,
    const word& name
)
:
    dcpRBFDrivenMotionSolver<motionSolver>(mesh, dict),
    cmpt_(direction(name.back() - 'x')),
    velocity_(name.starts_with("pointMotionU")),
    field_
    (
        IOobject
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        pointMesh::New(mesh)
    )
{
    drive(dcpRBFSettings::conditionsOf(field_, true));
    const char c = field_.name().back();
    Info<< dcpRBFMotionSolver::typeName << ": driven by " << field_.name()
        << " (component " << c << " of the point "
        << (velocity_ ? "velocity" : "displacement")
        << "): the points of the patches whose condition fixes the value move"
        << " in " << c << " as "
        << (
               velocity_
             ? "velocityComponentLaplacian moves them (deltaT times it each"
               " step)"
             : "displacementComponentLaplacian moves them"
           )
        << "; the rest is interpolated" << endl;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFComponentMotionSolver::prescribe()
{
    pointScalarField::Boundary& given = field_.boundaryFieldRef();
    given.updateCoeffs();
    const scalar deltaT = mesh().time().deltaTValue();
    const pointField& points = mesh().points();
    const pointField& points0 = driven_->points0();
    forAll(given, patchi)
    {
        if (!driven_->fixes(patchi))
        {
            continue;
        }
        const labelList& meshPoints = given[patchi].patch().meshPoints();
        const scalarField& u =
            refCast<const valuePointPatchField<scalar>>(given[patchi]);
        vectorField d
        (
            vectorField(points, meshPoints) - vectorField(points0, meshPoints)
        );
        forAll(d, i)
        {
            d[i][cmpt_] = velocity_ ? d[i][cmpt_] + deltaT*u[i] : u[i];
        }
        driven_->prescribe(patchi, d);
    }
}


void Foam::dcpRBFComponentMotionSolver::update(const pointField& newPoints)
{
    const scalarField c(newPoints.component(cmpt_));
    const scalar deltaT = mesh().time().deltaTValue();
    field_.primitiveFieldRef() =
        velocity_
      ? scalarField((c - mesh().points().component(cmpt_))/deltaT)
      : scalarField(c - driven_->points0().component(cmpt_));
    field_.correctBoundaryConditions();
}


// ************************************************************************* //
