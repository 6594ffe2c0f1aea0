/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFWingMotion.H"
#include "unitConversion.H"

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * * //

const Foam::Enum<Foam::dcpRBFWingMotion::deflectionShapeType>
Foam::dcpRBFWingMotion::deflectionShapeNames
({
    { deflectionShapeType::quadratic, "quadratic" },
    { deflectionShapeType::cubic, "cubic" },
    { deflectionShapeType::linear, "linear" },
    { deflectionShapeType::uniformLoadBeam, "uniformLoadBeam" },
});

const Foam::Enum<Foam::dcpRBFWingMotion::twistShapeType>
Foam::dcpRBFWingMotion::twistShapeNames
({
    { twistShapeType::linear, "linear" },
    { twistShapeType::quadratic, "quadratic" },
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// A non-zero vector entry, normalised; FatalIOError naming the keyword
Foam::vector unitEntry(const Foam::dictionary& dict, const Foam::word& key)
{
    Foam::vector v(dict.get<Foam::vector>(key));
    const Foam::scalar m = Foam::mag(v);
    if (m < Foam::VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << " " << v << " is a zero vector" << Foam::nl
            << Foam::exit(Foam::FatalIOError);
    }
    return v/m;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFWingMotion::dcpRBFWingMotion()
:
    root_(Zero),
    spanAxis_(0, 1, 0),
    deflectionDirection_(0, 0, 1),
    semiSpan_(1),
    deflectionShape_(deflectionShapeType::quadratic),
    twistShape_(twistShapeType::linear),
    twistAxisPoint_(Zero),
    twistAxisDirection_(spanAxis_)
{}


Foam::dcpRBFWingMotion::dcpRBFWingMotion(const dictionary& dict)
:
    root_(dict.get<point>("root")),
    spanAxis_(unitEntry(dict, "spanAxis")),
    deflectionDirection_(unitEntry(dict, "deflectionDirection")),
    semiSpan_(dict.get<scalar>("semiSpan")),
    deflectionShape_
    (
        deflectionShapeNames.getOrDefault
        (
            "deflectionShape", dict, deflectionShapeType::quadratic
        )
    ),
    twistShape_
    (
        twistShapeNames.getOrDefault("twistShape", dict, twistShapeType::linear)
    ),
    twistAxisPoint_(dict.getOrDefault<point>("twistAxisPoint", root_)),
    twistAxisDirection_(spanAxis_)
{
    if (mag(deflectionDirection_ & spanAxis_) > 1e-6)
    {
        FatalIOErrorInFunction(dict)
            << "Entry deflectionDirection " << deflectionDirection_
            << " is not normal to spanAxis " << spanAxis_
            << " (cosine " << (deflectionDirection_ & spanAxis_) << ")" << nl
            << exit(FatalIOError);
    }
    if (!(semiSpan_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry semiSpan " << semiSpan_ << " must be positive" << nl
            << exit(FatalIOError);
    }
    if (dict.found("twistAxisDirection"))
    {
        twistAxisDirection_ = unitEntry(dict, "twistAxisDirection");
        if (mag(twistAxisDirection_ & spanAxis_) < 1e-6)
        {
            FatalIOErrorInFunction(dict)
                << "Entry twistAxisDirection " << twistAxisDirection_
                << " is normal to spanAxis " << spanAxis_
                << ": the twist axis must cross every span station" << nl
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dcpRBFWingMotion::eta(const point& x0) const
{
    return min(max(((x0 - root_) & spanAxis_)/semiSpan_, scalar(0)), scalar(1));
}


Foam::scalar Foam::dcpRBFWingMotion::deflectionShape(const scalar e) const
{
    switch (deflectionShape_)
    {
        case deflectionShapeType::cubic: return e*e*e;
        case deflectionShapeType::linear: return e;
        case deflectionShapeType::uniformLoadBeam:
            return e*e*(6 - 4*e + e*e)/3;
        default: return e*e;
    }
}


Foam::scalar Foam::dcpRBFWingMotion::twistShape(const scalar e) const
{
    return twistShape_ == twistShapeType::quadratic ? e*e : e;
}


Foam::point Foam::dcpRBFWingMotion::twistAxisAt(const point& x0) const
{
    // The point of the line twistAxisPoint + t twistAxisDirection in the
    // plane normal to the span axis through x0
    const scalar t =
        ((x0 - twistAxisPoint_) & spanAxis_)/(twistAxisDirection_ & spanAxis_);
    return twistAxisPoint_ + t*twistAxisDirection_;
}


Foam::vector Foam::dcpRBFWingMotion::displacement
(
    const point& x0,
    const scalar tipDeflection,
    const scalar tipTwist
) const
{
    const scalar e = eta(x0);
    const scalar theta = tipTwist*twistShape(e);

    // Rodrigues about spanAxis through the local twist-axis point; r is
    // normal to the span axis by construction
    const vector r(x0 - twistAxisAt(x0));
    const vector rotation
    (
        r*(cos(theta) - 1)
      + (spanAxis_ ^ r)*sin(theta)
      + (spanAxis_ & r)*(1 - cos(theta))*spanAxis_
    );

    return rotation + tipDeflection*deflectionShape(e)*deflectionDirection_;
}


Foam::tmp<Foam::vectorField> Foam::dcpRBFWingMotion::displacement
(
    const pointField& x0,
    const scalar tipDeflection,
    const scalar tipTwist
) const
{
    auto td = tmp<vectorField>::New(x0.size());
    vectorField& d = td.ref();
    forAll(x0, i)
    {
        d[i] = displacement(x0[i], tipDeflection, tipTwist);
    }
    return td;
}


void Foam::dcpRBFWingMotion::write(Ostream& os) const
{
    os.writeEntry("root", root_);
    os.writeEntry("spanAxis", spanAxis_);
    os.writeEntry("deflectionDirection", deflectionDirection_);
    os.writeEntry("semiSpan", semiSpan_);
    os.writeEntry("deflectionShape", deflectionShapeNames[deflectionShape_]);
    os.writeEntry("twistShape", twistShapeNames[twistShape_]);
    os.writeEntry("twistAxisPoint", twistAxisPoint_);
    os.writeEntry("twistAxisDirection", twistAxisDirection_);
}



// ************************************************************************* //
