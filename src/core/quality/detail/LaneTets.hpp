// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: a cell's tetrahedron measured in a SIMD lane
// (PrismBatch, HexBatch: a cell per lane, its decomposition's tetrahedra
// computed in the lane). Include after TetKernel.hpp and LaneWorst.hpp,
// in the kernels' .cpp files only (their pragmas apply to these
// functions).
#pragma once

#include "LaneWorst.hpp"

#include <cstddef>

namespace dcprbf
{
namespace detail
{
namespace laneTets
{

//- A point, scalarised by the compiler (no array in the SIMD loop)
struct V3
{
    double x, y, z;
};

DCPRBF_ALWAYS_INLINE V3 operator+(const V3& a, const V3& b)
{
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}

DCPRBF_ALWAYS_INLINE V3 operator-(const V3& a, const V3& b)
{
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}

DCPRBF_ALWAYS_INLINE V3 operator/(const V3& a, const double b)
{
    return {a.x/b, a.y/b, a.z/b};
}


//- Tetrahedron (cell centre, face centre, a, b): reference edges from the
//  reference cell centre c0, current from c
template<int M>
DCPRBF_ALWAYS_INLINE void addTet
(
    LaneWorst& w,
    double* o,
    const std::size_t s,
    const int t,
    const V3& c0, const V3& f0, const V3& a0, const V3& b0,
    const V3& c, const V3& f, const V3& a, const V3& b
)
{
    const V3 e0 = f0 - c0, ea = a0 - c0, eb = b0 - c0;
    const V3 g0 = f - c, ga = a - c, gb = b - c;
    double J, a2;
    tetKernel::measures
    (
        e0.x, e0.y, e0.z, ea.x, ea.y, ea.z, eb.x, eb.y, eb.z,
        g0.x, g0.y, g0.z, ga.x, ga.y, ga.z, gb.x, gb.y, gb.z,
        J, a2
    );
    const double k = tetKernel::key<M>(J, a2);
    o[(5 + 2*t)*s] = J;
    o[(6 + 2*t)*s] = a2;

    w.add(J, a2, k);
}

} // namespace laneTets
} // namespace detail
} // namespace dcprbf
