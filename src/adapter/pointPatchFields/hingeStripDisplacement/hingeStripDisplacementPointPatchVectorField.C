/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "hingeStripDisplacementPointPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "pointPatchFields.H"
#include "transformField.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::hingeStripDisplacementPointPatchVectorField::readBlend
(
    const dictionary& dict
)
{
    hingePoint_ = dict.get<point>("hingePoint");
    blendDirection_ = dict.get<vector>("blendDirection");
    if (mag(blendDirection_) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "patch " << patch().name() << ": blendDirection "
            << blendDirection_ << " must be a non-zero vector"
            << exit(FatalIOError);
    }
    blendDirection_ /= mag(blendDirection_);
    blendStart_ = dict.get<scalar>("blendStart");
    blendEnd_ = dict.get<scalar>("blendEnd");
    if (!(blendEnd_ > blendStart_))
    {
        FatalIOErrorInFunction(dict)
            << "patch " << patch().name() << ": blendEnd " << blendEnd_
            << " must be greater than blendStart " << blendStart_
            << exit(FatalIOError);
    }
}


Foam::scalar Foam::hingeStripDisplacementPointPatchVectorField::blend
(
    const point& x0
) const
{
    const scalar d = (x0 - hingePoint_) & blendDirection_;
    const scalar t =
        min(max((d - blendStart_)/(blendEnd_ - blendStart_), 0.0), 1.0);
    return t*t*t*(10 - 15*t + 6*t*t);
}


Foam::tmp<Foam::vectorField>
Foam::hingeStripDisplacementPointPatchVectorField::displacement() const
{
    const septernion T(motion().transformation());
    const scalar moved = mag(T.transformPoint(hingePoint_) - hingePoint_);
    if (moved > 1e-6*(blendEnd_ - blendStart_))
    {
        FatalErrorInFunction
            << "patch " << patch().name() << " (" << typeName << "): the "
            << "solidBodyMotionFunction " << motion().type() << " moves "
            << "hingePoint " << hingePoint_ << " by " << moved << " at time "
            << db().time().timeName() << ": it must be a rotation about an "
            << "axis through hingePoint (set hingePoint on the motion's "
            << "axis, e.g. its origin)" << exit(FatalError);
    }

    // The turning part's displacement (as solidBodyMotionDisplacement
    // makes it, bit for bit), blended where 0 < s < 1
    // The rotation's axis and angle (the shorter way round), from the
    // quaternion's parts: atan2 is exact near rest, where slerp's acos would
    // turn a round-off rotation into one of 1e-8 rad
    const quaternion& q = T.r();
    const scalar sign = q.w() < 0 ? -1 : 1;
    const scalar sinHalf = mag(q.v());
    const scalar angle = 2*atan2(sinHalf, sign*q.w());
    const vector axis = sinHalf > 0 ? sign*q.v()/sinHalf : vector(1, 0, 0);

    const pointField& x0 = localPoints0();
    tmp<vectorField> td(transformPoints(T, x0) - x0);
    vectorField& d = td.ref();
    forAll(x0, i)
    {
        const scalar s = blend(x0[i]);
        if (s <= 0)
        {
            d[i] = Zero;
        }
        else if (s < 1)
        {
            const quaternion R(axis, s*angle);
            d[i] = R.transform(x0[i] - hingePoint_) + hingePoint_ - x0[i];
        }
    }
    return td;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::hingeStripDisplacementPointPatchVectorField::
hingeStripDisplacementPointPatchVectorField
(
    const pointPatch& p,
    const DimensionedField<vector, pointMesh>& iF
)
:
    solidBodyMotionDisplacementPointPatchVectorField(p, iF),
    hingePoint_(Zero),
    blendDirection_(1, 0, 0),
    blendStart_(0),
    blendEnd_(1)
{}


Foam::hingeStripDisplacementPointPatchVectorField::
hingeStripDisplacementPointPatchVectorField
(
    const pointPatch& p,
    const DimensionedField<vector, pointMesh>& iF,
    const dictionary& dict
)
:
    solidBodyMotionDisplacementPointPatchVectorField(p, iF, dict)
{
    readBlend(dict);
    if (!dict.found("value"))
    {
        fixedValuePointPatchVectorField::operator==(displacement());
    }
}


Foam::hingeStripDisplacementPointPatchVectorField::
hingeStripDisplacementPointPatchVectorField
(
    const hingeStripDisplacementPointPatchVectorField& ptf,
    const pointPatch& p,
    const DimensionedField<vector, pointMesh>& iF,
    const pointPatchFieldMapper& mapper
)
:
    solidBodyMotionDisplacementPointPatchVectorField(ptf, p, iF, mapper),
    hingePoint_(ptf.hingePoint_),
    blendDirection_(ptf.blendDirection_),
    blendStart_(ptf.blendStart_),
    blendEnd_(ptf.blendEnd_)
{
    // the base re-evaluated the whole rotation: the blend instead
    fixedValuePointPatchVectorField::operator==(displacement());
}


Foam::hingeStripDisplacementPointPatchVectorField::
hingeStripDisplacementPointPatchVectorField
(
    const hingeStripDisplacementPointPatchVectorField& ptf
)
:
    solidBodyMotionDisplacementPointPatchVectorField(ptf),
    hingePoint_(ptf.hingePoint_),
    blendDirection_(ptf.blendDirection_),
    blendStart_(ptf.blendStart_),
    blendEnd_(ptf.blendEnd_)
{}


Foam::hingeStripDisplacementPointPatchVectorField::
hingeStripDisplacementPointPatchVectorField
(
    const hingeStripDisplacementPointPatchVectorField& ptf,
    const DimensionedField<vector, pointMesh>& iF
)
:
    solidBodyMotionDisplacementPointPatchVectorField(ptf, iF),
    hingePoint_(ptf.hingePoint_),
    blendDirection_(ptf.blendDirection_),
    blendStart_(ptf.blendStart_),
    blendEnd_(ptf.blendEnd_)
{
    // the base re-evaluated the whole rotation: the blend instead
    fixedValuePointPatchVectorField::operator==(displacement());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::hingeStripDisplacementPointPatchVectorField::updateCoeffs()
{
    if (this->updated())
    {
        return;
    }
    fixedValuePointPatchVectorField::operator==(displacement());
    // not the base's: it would set the whole rotation
    fixedValuePointPatchVectorField::updateCoeffs();
}


void Foam::hingeStripDisplacementPointPatchVectorField::write
(
    Ostream& os
) const
{
    solidBodyMotionDisplacementPointPatchVectorField::write(os);
    os.writeEntry("hingePoint", hingePoint_);
    os.writeEntry("blendDirection", blendDirection_);
    os.writeEntry("blendStart", blendStart_);
    os.writeEntry("blendEnd", blendEnd_);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePointPatchTypeField
    (
        pointPatchVectorField,
        hingeStripDisplacementPointPatchVectorField
    );
}


// ************************************************************************* //
