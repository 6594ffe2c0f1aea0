// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the interface of a change of the control set phased
// in over steps. While active() the control set is solved blended
// (DynamicControlSet::solveBlended): its interpolant is
//
//     s = (1 - w) s_from + w s_this,     w = weight(), from = from(),
//
// so that the mesh velocity does not jump where the set changes. Whoever
// solves the set (the adapter's dcpRBFControlPoints::blendWith()) reads it;
// a swap rule owns it and says when it starts, advances and ends (SwapBlend
// is one).
//
// Contract: from() and weight() are called only while active(); from() is
// valid until the blend changes.
#pragma once

#include "DynamicControlSet.hpp"

namespace dcprbf
{

class SetBlend
{
public:
    virtual ~SetBlend() = default;

    //- Is a blend under way?
    virtual bool active() const = 0;

    //- The set being phased out (active() only)
    virtual const DynamicControlSet::State& from() const = 0;

    //- The weight w of the current set, in (0, 1] (active() only)
    virtual double weight() const = 0;
};

} // namespace dcprbf
