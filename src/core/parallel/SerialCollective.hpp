// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the collective operations of a single rank (every
// operation leaves the data as it is).
#pragma once

#include "Collective.hpp"

namespace dcprbf
{

class SerialCollective final : public Collective
{
public:
    using Collective::max;

    int size() const override { return 1; }
    int rank() const override { return 0; }
    void max(double*, Eigen::Index) const override {}
    void broadcast(double*, Eigen::Index, int) const override {}
    std::vector<Eigen::Index> allGather(Eigen::Index value) const override
    {
        return {value};
    }

    //- The one instance a serial problem needs (it holds no state)
    static const SerialCollective& instance()
    {
        static const SerialCollective serial;
        return serial;
    }
};

} // namespace dcprbf
