// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "HexBatch.hpp"

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

//- A hexahedron's 24 tetrahedra into w (each one's J and a2 into o, s
//  apart, from o[5 s]): vertices v0 .. v7 (reference r, current c); face
//  centres (vertex averages) and the cell centre (the average of the face
//  centres)
template<int M>
DCPRBF_ALWAYS_INLINE void addHex
(
    LaneWorst& w,
    double* o,
    const std::size_t s,
    const V3& r0, const V3& r1, const V3& r2, const V3& r3,
    const V3& r4, const V3& r5, const V3& r6, const V3& r7,
    const V3& c0, const V3& c1, const V3& c2, const V3& c3,
    const V3& c4, const V3& c5, const V3& c6, const V3& c7
)
{
    // faces: bottom (0 1 2 3), top (4 5 6 7), sides (i, i+1, i+5, i+4)
    const V3 rb = (r0 + r1 + r2 + r3)/4, rt = (r4 + r5 + r6 + r7)/4;
    const V3 rs0 = (r0 + r1 + r5 + r4)/4, rs1 = (r1 + r2 + r6 + r5)/4;
    const V3 rs2 = (r2 + r3 + r7 + r6)/4, rs3 = (r3 + r0 + r4 + r7)/4;
    const V3 rc = (rb + rt + rs0 + rs1 + rs2 + rs3)/6;
    const V3 cb = (c0 + c1 + c2 + c3)/4, ct = (c4 + c5 + c6 + c7)/4;
    const V3 cs0 = (c0 + c1 + c5 + c4)/4, cs1 = (c1 + c2 + c6 + c5)/4;
    const V3 cs2 = (c2 + c3 + c7 + c6)/4, cs3 = (c3 + c0 + c4 + c7)/4;
    const V3 cc = (cb + ct + cs0 + cs1 + cs2 + cs3)/6;

    // the bottom's and the top's edges, then each side's four
    addTet<M>(w, o, s, 0, rc, rb, r0, r1, cc, cb, c0, c1);
    addTet<M>(w, o, s, 1, rc, rb, r1, r2, cc, cb, c1, c2);
    addTet<M>(w, o, s, 2, rc, rb, r2, r3, cc, cb, c2, c3);
    addTet<M>(w, o, s, 3, rc, rb, r3, r0, cc, cb, c3, c0);
    addTet<M>(w, o, s, 4, rc, rt, r4, r5, cc, ct, c4, c5);
    addTet<M>(w, o, s, 5, rc, rt, r5, r6, cc, ct, c5, c6);
    addTet<M>(w, o, s, 6, rc, rt, r6, r7, cc, ct, c6, c7);
    addTet<M>(w, o, s, 7, rc, rt, r7, r4, cc, ct, c7, c4);
    #define DCPRBF_SIDE(t, k, ri, rj, rI, rJ, ci, cj, cI, cJ)                       \
        addTet<M>(w, o, s, t, rc, rs##k, ri, rj, cc, cs##k, ci, cj);             \
        addTet<M>(w, o, s, t + 1, rc, rs##k, rj, rJ, cc, cs##k, cj, cJ);         \
        addTet<M>(w, o, s, t + 2, rc, rs##k, rJ, rI, cc, cs##k, cJ, cI);         \
        addTet<M>(w, o, s, t + 3, rc, rs##k, rI, ri, cc, cs##k, cI, ci)
    DCPRBF_SIDE(8, 0, r0, r1, r4, r5, c0, c1, c4, c5);
    DCPRBF_SIDE(12, 1, r1, r2, r5, r6, c1, c2, c5, c6);
    DCPRBF_SIDE(16, 2, r2, r3, r6, r7, c2, c3, c6, c7);
    DCPRBF_SIDE(20, 3, r3, r0, r7, r4, c3, c0, c7, c4);
    #undef DCPRBF_SIDE
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
    addHex<M>
    (
        w, out + p, s,
        DCPRBF_V3(0), DCPRBF_V3(1), DCPRBF_V3(2), DCPRBF_V3(3),
        DCPRBF_V3(4), DCPRBF_V3(5), DCPRBF_V3(6), DCPRBF_V3(7),
        DCPRBF_V3(8), DCPRBF_V3(9), DCPRBF_V3(10), DCPRBF_V3(11),
        DCPRBF_V3(12), DCPRBF_V3(13), DCPRBF_V3(14), DCPRBF_V3(15)
    );
    #undef DCPRBF_V3
    w.write(out, p, s);
}
};

} // namespace


void HexBatch::measure(const TetQuality::Metric metric, const bool wide)
{
    tetKernel::dispatch<tetKernel::Lanes<Lane>>
    (
        metric, wide, lanes_.size(), lanes_.stride(), lanes_.inData(), lanes_.outData()
    );
}

} // namespace detail
} // namespace dcprbf
