// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the worst tetrahedron of many hexahedra at once,
// one hexahedron per SIMD lane (CellQualityScan's hexahedral cells: most of
// a snappyHexMesh or blockMesh mesh). PrismBatch's counterpart.
//
// A hexahedron is given by its eight vertices, reference and current: a
// quadrilateral (0 1 2 3) and the points joined to its points (4 5 6 7).
// Its decomposition is CellQualityScan's: face centres (vertex averages),
// the cell centre (the average of the six face centres) and the 24
// tetrahedra (cell centre, face centre, face edge), computed in the lane
// instead of gathered into a TetBatch; a tetrahedron's A does not depend
// on the order of its vertices, so neither the faces' orientation nor
// their point order matters (the face centres' sums, in another order
// than the faces', differ in round-off only). measure() keeps per
// hexahedron what TetMeasures::Worst keeps: the ranked worst (J, |A|^2 of
// the least rank key), the least quality of the inverted (J) and
// degenerate (1) ones, and whether a tetrahedron is beyond the key's range
// (exact() false; the caller ranks that hexahedron's 24 tetrahedra, kept,
// with TetMeasures::Worst).
#pragma once

#include "LaneArrays.hpp"
#include "TetMeasures.hpp"
#include "TetQuality.hpp"

#include <cstddef>
#include <vector>

namespace dcprbf
{
namespace detail
{

class HexBatch
{
public:
    //- Room for n hexahedra (their values undefined until set)
    void resize(const std::size_t n) { lanes_.resize(n); }

    //- Number of hexahedra
    std::size_t size() const { return lanes_.size(); }

    //- Hexahedron p: vertex k's reference coordinates at r0 + 3 v[k],
    //  current at x + 3 v[k]
    inline void set
    (
        const std::size_t p,
        const double* r0,
        const double* x,
        const int v[8]
    )
    {
        for (int k = 0; k < 8; ++k)
        {
            const double* r = r0 + 3*std::size_t(v[k]);
            const double* y = x + 3*std::size_t(v[k]);
            for (int d = 0; d < 3; ++d)
            {
                lanes_.in(3*k + d, p) = r[d];
                lanes_.in(24 + 3*k + d, p) = y[d];
            }
        }
    }

    //- The worst tetrahedron of every hexahedron
    //  (wide false: the default-target build even with AVX2 or AVX-512;
    //  the values are the same)
    void measure(TetQuality::Metric metric, bool wide = true);

    //- Hexahedron p: all its tetrahedra were ranked or inverted or degenerate
    //  (no scalar path needed)
    bool exact(const std::size_t p) const { return lanes_.out(4, p) == 0; }

    //- Hexahedron p: J and |A|_F^2 of the ranked worst; ranked(p) false if
    //  every tetrahedron is inverted or degenerate
    double J(const std::size_t p) const { return lanes_.out(0, p); }
    double a2(const std::size_t p) const { return lanes_.out(1, p); }
    bool ranked(const std::size_t p) const { return lanes_.out(2, p) < 1e308; }

    //- Hexahedron p: the least quality of its inverted and degenerate
    //  tetrahedra (1e308 if none)
    double other(const std::size_t p) const { return lanes_.out(3, p); }

    //- Hexahedron p (exact) as TetMeasures::Worst keeps it
    TetMeasures::Worst worst(const std::size_t p, const TetQuality::Metric metric) const
    {
        return TetMeasures::Worst(metric, J(p), a2(p), ranked(p), other(p));
    }

    //- Hexahedron p: J and |A|_F^2 of its tetrahedron t (0 .. 23; for
    //  the scalar path)
    double tetJ(const std::size_t p, const int t) const
    {
        return lanes_.out(5 + 2*t, p);
    }
    double tetA2(const std::size_t p, const int t) const
    {
        return lanes_.out(6 + 2*t, p);
    }

private:
    //- In: 48 components (8 reference then 8 current vertices, x y z
    //  each); out: J, a2, key, other, the number beyond the key's range,
    //  then J and a2 of each of the 24 tetrahedra
    LaneArrays lanes_{48, 53};
};

} // namespace detail
} // namespace dcprbf
