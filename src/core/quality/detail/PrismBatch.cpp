// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "PrismBatch.hpp"

#include "TetKernel.hpp"
#include "LaneWorst.hpp"
#include "LaneTets.hpp"

#include <algorithm>

namespace dcprbf
{
namespace detail
{

namespace
{

using laneTets::V3;
using laneTets::addTet;

//- A prism's 18 tetrahedra into w (each one's J and a2 into o, s apart,
//  from o[5 s]): vertices v0 .. v5 (reference r, current
//  c); face centres (vertex averages) and the cell centre (the average of
//  the face centres)
template<int M>
DCPRBF_ALWAYS_INLINE void addPrism
(
    LaneWorst& w,
    double* o,
    const std::size_t s,
    const V3& r0, const V3& r1, const V3& r2, const V3& r3, const V3& r4, const V3& r5,
    const V3& c0, const V3& c1, const V3& c2, const V3& c3, const V3& c4, const V3& c5
)
{
    // faces: bottom, top, quads (0 1 4 3), (1 2 5 4), (2 0 3 5)
    const V3 rb = (r0 + r1 + r2)/3, rt = (r3 + r4 + r5)/3;
    const V3 rq0 = (r0 + r1 + r4 + r3)/4, rq1 = (r1 + r2 + r5 + r4)/4, rq2 = (r2 + r0 + r3 + r5)/4;
    const V3 rc = (rb + rt + rq0 + rq1 + rq2)/5;
    const V3 cb = (c0 + c1 + c2)/3, ct = (c3 + c4 + c5)/3;
    const V3 cq0 = (c0 + c1 + c4 + c3)/4, cq1 = (c1 + c2 + c5 + c4)/4, cq2 = (c2 + c0 + c3 + c5)/4;
    const V3 cc = (cb + ct + cq0 + cq1 + cq2)/5;

    addTet<M>(w, o, s, 0, rc, rb, r0, r1, cc, cb, c0, c1);
    addTet<M>(w, o, s, 1, rc, rb, r1, r2, cc, cb, c1, c2);
    addTet<M>(w, o, s, 2, rc, rb, r2, r0, cc, cb, c2, c0);
    addTet<M>(w, o, s, 3, rc, rt, r3, r4, cc, ct, c3, c4);
    addTet<M>(w, o, s, 4, rc, rt, r4, r5, cc, ct, c4, c5);
    addTet<M>(w, o, s, 5, rc, rt, r5, r3, cc, ct, c5, c3);
    addTet<M>(w, o, s, 6, rc, rq0, r0, r1, cc, cq0, c0, c1);
    addTet<M>(w, o, s, 7, rc, rq0, r1, r4, cc, cq0, c1, c4);
    addTet<M>(w, o, s, 8, rc, rq0, r4, r3, cc, cq0, c4, c3);
    addTet<M>(w, o, s, 9, rc, rq0, r3, r0, cc, cq0, c3, c0);
    addTet<M>(w, o, s, 10, rc, rq1, r1, r2, cc, cq1, c1, c2);
    addTet<M>(w, o, s, 11, rc, rq1, r2, r5, cc, cq1, c2, c5);
    addTet<M>(w, o, s, 12, rc, rq1, r5, r4, cc, cq1, c5, c4);
    addTet<M>(w, o, s, 13, rc, rq1, r4, r1, cc, cq1, c4, c1);
    addTet<M>(w, o, s, 14, rc, rq2, r2, r0, cc, cq2, c2, c0);
    addTet<M>(w, o, s, 15, rc, rq2, r0, r3, cc, cq2, c0, c3);
    addTet<M>(w, o, s, 16, rc, rq2, r3, r5, cc, cq2, c3, c5);
    addTet<M>(w, o, s, 17, rc, rq2, r5, r2, cc, cq2, c5, c2);
}


struct Lane
{
template<int M>
static DCPRBF_ALWAYS_INLINE void item
(
    const std::size_t p,
    const std::size_t s,
    const double* __restrict in,
    double* __restrict out
)
{
    const double* v = in + p;
    #define DCPRBF_V3(k) V3{v[(3*(k))*s], v[(3*(k) + 1)*s], v[(3*(k) + 2)*s]}
    LaneWorst w;
    addPrism<M>
    (
        w, out + p, s,
        DCPRBF_V3(0), DCPRBF_V3(1), DCPRBF_V3(2), DCPRBF_V3(3), DCPRBF_V3(4), DCPRBF_V3(5),
        DCPRBF_V3(6), DCPRBF_V3(7), DCPRBF_V3(8), DCPRBF_V3(9), DCPRBF_V3(10), DCPRBF_V3(11)
    );
    #undef DCPRBF_V3
    w.write(out, p, s);
}
};

} // namespace


void PrismBatch::measure(const TetQuality::Metric metric, const bool wide)
{
    tetKernel::dispatch<tetKernel::Lanes<Lane>>
    (
        metric, wide, lanes_.size(), lanes_.stride(), lanes_.inData(), lanes_.outData()
    );
}

} // namespace detail
} // namespace dcprbf
