/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFPstreamCollective.H"
#include "dcpRBFVersion.H"
#include "PstreamReduceOps.H"
#include "scalarList.H"
#include "labelList.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

int Foam::dcpRBFPstreamCollective::size() const
{
    return Pstream::nProcs();
}


int Foam::dcpRBFPstreamCollective::rank() const
{
    return Pstream::myProcNo();
}


void Foam::dcpRBFPstreamCollective::max(double* v, Eigen::Index n) const
{
    for (Eigen::Index k = 0; k < n; ++k)
    {
        reduce(v[k], maxOp<scalar>());
    }
}


void Foam::dcpRBFPstreamCollective::broadcast
(
    double* v,
    Eigen::Index n,
    int root
) const
{
    List<scalarList> all(Pstream::nProcs());
    if (Pstream::myProcNo() == root)
    {
        all[root] = scalarList(label(n));
        std::copy(v, v + n, all[root].begin());
    }
    dcpRBFCompat::allGatherList(all);
    std::copy(all[root].begin(), all[root].end(), v);
}


std::vector<Eigen::Index> Foam::dcpRBFPstreamCollective::allGather
(
    Eigen::Index value
) const
{
    labelList all(Pstream::nProcs());
    all[Pstream::myProcNo()] = label(value);
    dcpRBFCompat::allGatherList(all);
    return std::vector<Eigen::Index>(all.begin(), all.end());
}


// ************************************************************************* //
