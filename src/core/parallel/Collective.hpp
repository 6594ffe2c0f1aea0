// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the collective operations a problem divided over
// ranks (processors) needs, and nothing else. The core stays free of MPI:
// the OpenFOAM adapter implements them with Pstream (dcpRBFPstreamCollective),
// the core's tests with threads that stand for ranks (tests/core/parallel),
// and a single process with SerialCollective.
//
// Every rank calls every operation in the same order with the same sizes
// (collective calls); the results are the same on every rank, bit for bit.
#pragma once

#include "Types.hpp"

#include <vector>

namespace dcprbf
{

class Collective
{
public:
    virtual ~Collective() = default;

    //- Number of ranks (>= 1)
    virtual int size() const = 0;

    //- This rank, in [0, size())
    virtual int rank() const = 0;

    //- v[0 .. n) replaced by its element-wise maximum over the ranks
    virtual void max(double* v, Eigen::Index n) const = 0;

    //- v[0 .. n) replaced by root's v[0 .. n) (n the same on every rank)
    virtual void broadcast(double* v, Eigen::Index n, int root) const = 0;

    //- Every rank's value, in rank order
    virtual std::vector<Eigen::Index> allGather(Eigen::Index value) const = 0;

    //- The largest value over the ranks (a convenience on max())
    double max(double value) const
    {
        max(&value, 1);
        return value;
    }

    //- Is the condition true on any rank? (all ranks agree, e.g. to throw
    //  the same Error everywhere instead of leaving ranks waiting)
    bool any(bool condition) const
    {
        return max(condition ? 1.0 : 0.0) > 0;
    }
};

} // namespace dcprbf
