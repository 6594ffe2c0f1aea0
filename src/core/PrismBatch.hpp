// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the worst tetrahedron of many triangular prisms at
// once, one prism per SIMD lane (CellQualityScan's prism cells: the
// boundary layers of 3D meshes).
//
// A prism is given by its six vertices, reference and current: a triangle
// (0 1 2) and the points above its points (3 4 5). Its decomposition is
// CellQualityScan's: face centres (vertex averages), the cell centre (the
// average of the five face centres) and the 18 tetrahedra (cell centre,
// face centre, face edge); a tetrahedron's A does not depend on the order
// of its vertices, so neither the faces' orientation nor their point order
// matters. measure() computes every tetrahedron (tetKernel) and keeps per
// prism what TetMeasures::Worst keeps: the ranked worst (J, |A|^2 of the
// least rank key), the least quality of the inverted (J) and degenerate (1)
// ones, and whether a tetrahedron is beyond the key's range (positive J,
// key 0 or below 1e-250: exact() false; the caller ranks that prism's 18
// tetrahedra, kept, with TetMeasures::Worst).
#pragma once

#include "TetMeasures.hpp"
#include "TetQuality.hpp"

#include <cstddef>
#include <vector>

namespace dcprbf
{

class PrismBatch
{
public:
    //- Room for n prisms (their values undefined until set)
    void resize(std::size_t n);

    //- Number of prisms
    std::size_t size() const { return n_; }

    //- Prism p: vertex k's reference coordinates at r0 + 3 v[k], current at
    //  x + 3 v[k]
    inline void set
    (
        const std::size_t p,
        const double* r0,
        const double* x,
        const int v[6]
    )
    {
        double* c = data_.data() + p;
        for (int k = 0; k < 6; ++k)
        {
            const double* r = r0 + 3*std::size_t(v[k]);
            const double* y = x + 3*std::size_t(v[k]);
            for (int d = 0; d < 3; ++d)
            {
                c[(3*k + d)*stride_] = r[d];
                c[(18 + 3*k + d)*stride_] = y[d];
            }
        }
    }

    //- The worst tetrahedron of every prism
    //  (wide false: the default-target build even where AVX2 is there;
    //  the values are the same)
    void measure(TetQuality::Metric metric, bool wide = true);

    //- Prism p: all its tetrahedra were ranked or inverted or degenerate
    //  (no scalar path needed)
    bool exact(const std::size_t p) const { return out_[4*stride_ + p] == 0; }

    //- Prism p: J and |A|_F^2 of the ranked worst; ranked(p) false if
    //  every tetrahedron is inverted or degenerate
    double J(const std::size_t p) const { return out_[p]; }
    double a2(const std::size_t p) const { return out_[stride_ + p]; }
    bool ranked(const std::size_t p) const { return out_[2*stride_ + p] < 1e308; }

    //- Prism p: the least quality of its inverted and degenerate
    //  tetrahedra (1e308 if none)
    double other(const std::size_t p) const { return out_[3*stride_ + p]; }

    //- Prism p (exact) as TetMeasures::Worst keeps it
    TetMeasures::Worst worst(const std::size_t p, const TetQuality::Metric metric) const
    {
        return TetMeasures::Worst(metric, J(p), a2(p), ranked(p), other(p));
    }

    //- Prism p: J and |A|_F^2 of its tetrahedron t (0 .. 17; for the
    //  scalar path)
    double tetJ(const std::size_t p, const int t) const
    {
        return out_[(5 + 2*std::size_t(t))*stride_ + p];
    }
    double tetA2(const std::size_t p, const int t) const
    {
        return out_[(6 + 2*std::size_t(t))*stride_ + p];
    }

private:
    //- Number of prisms, room per component
    std::size_t n_ = 0, stride_ = 0;

    //- 36 components (6 reference then 6 current vertices, x y z each),
    //  stride_ apart
    std::vector<double> data_;

    //- J, a2, key, other, the number beyond the key's range, then J and
    //  a2 of each of the 18 tetrahedra, stride_ apart
    std::vector<double> out_;
};

} // namespace dcprbf
