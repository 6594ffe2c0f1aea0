// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "SetTransaction.hpp"

#include <utility>

namespace dcprbf
{

void SetTransaction::begin(DynamicControlSet::State before)
{
    if (before_)
    {
        throw Error("SetTransaction::begin: a transaction is already open");
    }
    before_.reset(new DynamicControlSet::State(std::move(before)));
}


const DynamicControlSet::State& SetTransaction::before() const
{
    if (!before_)
    {
        throw Error("SetTransaction::before: no transaction open");
    }
    return *before_;
}


void SetTransaction::commit()
{
    if (!before_)
    {
        throw Error("SetTransaction::commit: no transaction open");
    }
    before_.reset();
}


void SetTransaction::rollBack()
{
    if (!before_)
    {
        throw Error("SetTransaction::rollBack: no transaction open");
    }
    set_.restore(*before_);
    before_.reset();
}

} // namespace dcprbf
