/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "wingBendingTwistDisplacementPointPatchVectorField.H"
#include "pointPatchFields.H"
#include "addToRunTimeSelectionTable.H"
#include "Time.H"
#include "unitConversion.H"
#include "Constant.H"
#include "dcpRBFVersion.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wingBendingTwistDisplacementPointPatchVectorField::
wingBendingTwistDisplacementPointPatchVectorField
(
    const pointPatch& p,
    const DimensionedField<vector, pointMesh>& iF
)
:
    fixedValuePointPatchField<vector>(p, iF),
    motion_(),
    tipDeflection_(new Function1Types::Constant<scalar>("tipDeflection", 0)),
    tipTwist_(new Function1Types::Constant<scalar>("tipTwist", 0)),
    p0_(p.localPoints())
{}


Foam::wingBendingTwistDisplacementPointPatchVectorField::
wingBendingTwistDisplacementPointPatchVectorField
(
    const pointPatch& p,
    const DimensionedField<vector, pointMesh>& iF,
    const dictionary& dict
)
:
    fixedValuePointPatchField<vector>(p, iF, dict, false),
    motion_(dict),
    tipDeflection_
    (
        dcpRBFCompat::newFunction1<scalar>("tipDeflection", dict, this->db())
    ),
    tipTwist_
    (
        dcpRBFCompat::newFunction1<scalar>("tipTwist", dict, this->db())
    ),
    p0_(p.localPoints())
{
    if (dict.found("p0"))
    {
        p0_ = vectorField("p0", dict, p.size());
    }

    if (!dict.found("value"))
    {
        updateCoeffs();
    }
}


Foam::wingBendingTwistDisplacementPointPatchVectorField::
wingBendingTwistDisplacementPointPatchVectorField
(
    const wingBendingTwistDisplacementPointPatchVectorField& ptf,
    const pointPatch& p,
    const DimensionedField<vector, pointMesh>& iF,
    const pointPatchFieldMapper& mapper
)
:
    fixedValuePointPatchField<vector>(ptf, p, iF, mapper),
    motion_(ptf.motion_),
    tipDeflection_(ptf.tipDeflection_.clone()),
    tipTwist_(ptf.tipTwist_.clone()),
    p0_(ptf.p0_, mapper)
{}


Foam::wingBendingTwistDisplacementPointPatchVectorField::
wingBendingTwistDisplacementPointPatchVectorField
(
    const wingBendingTwistDisplacementPointPatchVectorField& ptf
)
:
    fixedValuePointPatchField<vector>(ptf),
    motion_(ptf.motion_),
    tipDeflection_(ptf.tipDeflection_.clone()),
    tipTwist_(ptf.tipTwist_.clone()),
    p0_(ptf.p0_)
{}


Foam::wingBendingTwistDisplacementPointPatchVectorField::
wingBendingTwistDisplacementPointPatchVectorField
(
    const wingBendingTwistDisplacementPointPatchVectorField& ptf,
    const DimensionedField<vector, pointMesh>& iF
)
:
    fixedValuePointPatchField<vector>(ptf, iF),
    motion_(ptf.motion_),
    tipDeflection_(ptf.tipDeflection_.clone()),
    tipTwist_(ptf.tipTwist_.clone()),
    p0_(ptf.p0_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::wingBendingTwistDisplacementPointPatchVectorField::autoMap
(
    const pointPatchFieldMapper& m
)
{
    fixedValuePointPatchField<vector>::autoMap(m);
    p0_.autoMap(m);
}


void Foam::wingBendingTwistDisplacementPointPatchVectorField::rmap
(
    const pointPatchField<vector>& ptf,
    const labelList& addr
)
{
    const auto& wptf =
        refCast<const wingBendingTwistDisplacementPointPatchVectorField>(ptf);

    fixedValuePointPatchField<vector>::rmap(wptf, addr);
    p0_.rmap(wptf.p0_, addr);
}


void Foam::wingBendingTwistDisplacementPointPatchVectorField::updateCoeffs()
{
    if (this->updated())
    {
        return;
    }

    const scalar t = this->db().time().timeOutputValue();

    vectorField::operator=
    (
        motion_.displacement(p0_, tipDeflection(t), degToRad(tipTwist(t)))
    );

    fixedValuePointPatchField<vector>::updateCoeffs();
}


void Foam::wingBendingTwistDisplacementPointPatchVectorField::write
(
    Ostream& os
) const
{
    pointPatchField<vector>::write(os);
    motion_.write(os);
    tipDeflection_->writeData(os);
    tipTwist_->writeData(os);
    p0_.writeEntry("p0", os);
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePointPatchTypeField
    (
        pointPatchVectorField,
        wingBendingTwistDisplacementPointPatchVectorField
    );
}

// ************************************************************************* //
