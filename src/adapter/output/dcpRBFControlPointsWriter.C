/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFControlPointsWriter.H"
#include "OFstream.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFControlPointsWriter::dcpRBFControlPointsWriter
(
    const Time& time,
    const dcpRBFPlaneProjection& projection,
    const dcpRBFBoundaryPoints& boundaryPoints
)
:
    time_(time),
    projection_(projection),
    boundaryPoints_(boundaryPoints)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dcpRBFControlPointsWriter::write
(
    const dcprbf::DynamicControlSet& set,
    const dcprbf::Values& d
) const
{
    if (!Pstream::master())
    {
        return;
    }
    const Time& t = time_;
    const fileName dir(t.rootPath()/t.globalCaseName()/"postProcessing"/"dcpRBF");
    mkDir(dir);
    OFstream os(dir/"controlPoints_" + t.timeName() + ".vtk");
    const std::vector<Eigen::Index>& idx = set.indices();
    os  << "# vtk DataFile Version 2.0" << nl
        << "dcpRBF control points at time " << t.timeName() << nl
        << "ASCII" << nl << "DATASET POLYDATA" << nl
        << "POINTS " << idx.size() << " double" << nl;
    for (const Eigen::Index i : idx)
    {
        const point x0(projection_.pointFromCore(boundaryPoints_.points().row(i).data()));
        const point x(x0 + projection_.fromCore(d.row(i).data()));
        os  << x.x() << ' ' << x.y() << ' ' << x.z() << nl;
    }
    os  << "VERTICES " << idx.size() << ' ' << 2*idx.size() << nl;
    for (std::size_t k = 0; k < idx.size(); ++k) os << "1 " << k << nl;
    os  << "POINT_DATA " << idx.size() << nl
        << "SCALARS moving int 1" << nl << "LOOKUP_TABLE default" << nl;
    for (const Eigen::Index i : idx) os << int(boundaryPoints_.moving()[i]) << nl;
    os  << "SCALARS age int 1" << nl << "LOOKUP_TABLE default" << nl;
    for (const int a : set.ages()) os << a << nl;
}


// ************************************************************************* //
