// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: a transaction on a DynamicControlSet, for changes
// that are tried and then kept or given up (the error-guided trial swaps).
// begin() records the set's state before the changes; commit() keeps them
// (the record is dropped), rollBack() puts the set back exactly as recorded:
// its indices, ages and factorization, bit for bit (DynamicControlSet::
// restore()), so that solving it again gives the same coefficients.
//
// Cost: begin() copies a state (O(N^2) numbers: the factorization), commit()
// O(1), rollBack() O(N^2) copies. No floating-point operation.
//
// Contract:
//  - One transaction is open at a time on one object (begin() on an open
//    one: Error); before(), commit() and rollBack() need it open (Error
//    otherwise). It holds a reference to the set: the set outlives it.
//  - Nothing is done on destruction: an open transaction forgotten leaves
//    the set as it is (the changes stay).
#pragma once

#include "DynamicControlSet.hpp"

#include <memory>

namespace dcprbf
{

class SetTransaction
{
public:
    //- A transaction on set, none open
    explicit SetTransaction(DynamicControlSet& set) : set_(set) {}

    //- Open it with the set's state before the changes (e.g. set.state(),
    //  taken where it should be: the leave-one-out errors it keeps)
    void begin(DynamicControlSet::State before);

    //- Is one open?
    bool open() const { return bool(before_); }

    //- The set as it was at begin() (open() only)
    const DynamicControlSet::State& before() const;

    //- The changes stay; closes it
    void commit();

    //- The set as at begin(); closes it
    void rollBack();

private:
    DynamicControlSet& set_;
    std::unique_ptr<DynamicControlSet::State> before_;   // null: none open
};

} // namespace dcprbf
