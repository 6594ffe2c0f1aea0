/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFControlPoints, continued: what to change when the core refuses
    the set, naming the keywords.
\*---------------------------------------------------------------------------*/

#include "dcpRBFControlPoints.H"
Foam::string Foam::dcpRBFControlPoints::whatToDo(const dcprbf::Error& e) const
{
    const std::string what(e.what());
    const dcprbf::RadialKernel& k = settings_.kernel();
    const string radius(" (supportRadius " + Foam::name(k.radius()) + ")");
    if
    (
        what.find("not positive definite") != std::string::npos
     || what.find("numerically dependent") != std::string::npos
    )
    {
        if (!k.compact())
        {
            return
                "function " + k.name() + " is global: supportRadius is its"
                " shape length" + radius + ", and its matrix is singular to"
                " round-off when that is large against the spacing of the"
                " boundary points. Take supportRadius of a few spacings of"
                " the boundary points, or a compactly supported function"
                " (function WendlandC2; supportRadius several times the"
                " largest displacement)";
        }
        return
            "the kernel matrix is singular to round-off: supportRadius"
          + radius + " is very large against the spacing of the boundary"
            " points (take selection greedy, which selects the points the"
            " interpolant needs, or a smaller supportRadius), or two"
            " boundary points of movingPatches and staticPatches coincide"
            " (a patch listed twice under other names or groups, or the two"
            " sides of an interface: list each once)";
    }
    if
    (
        what.find("collinear") != std::string::npos
     || what.find("coplanar") != std::string::npos
    )
    {
        return
            "the candidates are the points of movingPatches and"
            " staticPatches; with the polynomial they must span the space"
            " (not all on one line in 2D, not all in one plane in 3D): add a"
            " patch off that plane to staticPatches, or set polynomial false";
    }
    return "check movingPatches, staticPatches and controlPoints";
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //


// ************************************************************************* //
