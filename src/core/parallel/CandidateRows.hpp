// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: candidate points (coordinates and displacements)
// divided over the ranks of a Collective in consecutive blocks of one global
// numbering: rank r holds the global rows [begin(r), begin(r + 1)), in rank
// order. A rank may hold none.
//
// What a selection needs across the blocks: the global best of per-rank
// values (ties to the lowest global index, as a serial scan in global order
// breaks them, so that the choice does not depend on the division), and a
// row's data fetched from the rank that holds it. A single rank
// (SerialCollective) is the serial problem: global index = local index.
#pragma once

#include "Collective.hpp"

#include <vector>

namespace dcprbf
{

class CandidateRows
{
public:
    //- This rank's block of candidates x with values d (same row count);
    //  keeps references to all three (collective: every rank constructs)
    CandidateRows(const Collective& comm, const Points& x, const Values& d);

    //- The serial problem (SerialCollective)
    CandidateRows(const Points& x, const Values& d);

    const Collective& comm() const { return *comm_; }

    //- This rank's candidates and their values
    const Points& points() const { return *x_; }
    const Values& values() const { return *d_; }

    //- Number of this rank's candidates, of all ranks' candidates
    Eigen::Index size() const { return x_->rows(); }
    Eigen::Index total() const { return start_.back(); }

    //- Global index of this rank's first candidate
    Eigen::Index begin() const { return start_[comm_->rank()]; }

    //- The rank holding global row i
    int owner(Eigen::Index i) const;

    //- Local index of global row i, -1 where another rank holds it
    Eigen::Index local(Eigen::Index i) const
    {
        const Eigen::Index l = i - begin();
        return l >= 0 && l < size() ? l : -1;
    }

    //- A global choice: the value and the global index (-1: none)
    struct Best
    {
        double value;
        Eigen::Index index;
    };

    //- The best over the ranks: each rank passes its own best value and
    //  its local index (-1: none on this rank); returns the largest value
    //  and its global index, ties to the lowest global index (collective)
    Best argmax(double value, Eigen::Index localIndex) const;

    //- Global row i's coordinates (out[0..3)), values (out[3..6)) and n
    //  more doubles (extra: the owner's, read only there) on every rank
    //  (collective)
    void fetch
    (
        Eigen::Index i,
        const double* extra,
        Eigen::Index n,
        double* out
    ) const;

private:
    const Collective* comm_;
    const Points* x_;
    const Values* d_;

    //- Global index of each rank's first row; start_[size()] = total
    std::vector<Eigen::Index> start_;
};

} // namespace dcprbf
