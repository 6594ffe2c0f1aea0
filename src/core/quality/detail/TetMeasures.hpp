// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the tetrahedron quality of TetQuality for tight
// loops (header-only, inlined; no Eigen temporaries): the two measures J and
// |A|_F^2 from the vertices (E0^-1 by cross products), the quality from
// them, and a key that ranks tetrahedra as their quality does without cbrt
// and sqrt, so a cell's worst tetrahedron needs one cbrt.
#pragma once

#include "TetQuality.hpp"

#include <algorithm>
#include <cmath>

namespace dcprbf
{
namespace detail
{

struct TetMeasures
{
    //- a x b into c
    static inline void cross(const double* a, const double* b, double* c)
    {
        c[0] = a[1]*b[2] - a[2]*b[1];
        c[1] = a[2]*b[0] - a[0]*b[2];
        c[2] = a[0]*b[1] - a[1]*b[0];
    }

    //- a . b
    static inline double dot(const double* a, const double* b)
    {
        return a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
    }

    //- J and |A|_F^2 of the tetrahedron (r0 .. r3) moved to (c0 .. c3);
    //  a degenerate reference gives J = a2 = -1
    static inline void measures
    (
        const double* r0, const double* r1, const double* r2, const double* r3,
        const double* c0, const double* c1, const double* c2, const double* c3,
        double& J,
        double& a2
    )
    {
        // Edge matrices (columns e_k, f_k: edges from vertex 0)
        double e[3][3], f[3][3];
        for (int d = 0; d < 3; ++d)
        {
            e[0][d] = r1[d] - r0[d]; e[1][d] = r2[d] - r0[d]; e[2][d] = r3[d] - r0[d];
            f[0][d] = c1[d] - c0[d]; f[1][d] = c2[d] - c0[d]; f[2][d] = c3[d] - c0[d];
        }
        // E0^-1 = (rows e1 x e2, e2 x e0, e0 x e1)/det0
        double adj[3][3];
        cross(e[1], e[2], adj[0]);
        cross(e[2], e[0], adj[1]);
        cross(e[0], e[1], adj[2]);
        const double det0 = dot(e[0], adj[0]);
        const double scale2 = std::max({dot(e[0], e[0]), dot(e[1], e[1]), dot(e[2], e[2])});
        if (!(det0*det0 > 1e-28*scale2*scale2*scale2))
        {
            J = a2 = -1;   // degenerate reference (TetQuality::compute: q = 1)
            return;
        }
        double f12[3];
        cross(f[1], f[2], f12);
        J = dot(f[0], f12)/det0;
        // |A|_F^2, A det0 = E adj: (E adj)_ij = sum_k f_k[i] adj_k[j]
        a2 = 0;
        for (int i = 0; i < 3; ++i)
        {
            for (int j = 0; j < 3; ++j)
            {
                const double v = f[0][i]*adj[0][j] + f[1][i]*adj[1][j] + f[2][i]*adj[2][j];
                a2 += v*v;
            }
        }
        a2 /= det0*det0;
    }

    //- The quality from J and |A|_F^2 (a2 < 0: degenerate reference, 1);
    //  for J > 0 rankKey gives q^6 (sizeShape), q^3 (shape), q (size):
    //  increasing in the quality; tetQuality: TetQuality::compute to
    //  round-off
    static inline double quality(const double J, const double a2, const TetQuality::Metric metric)
    {
        if (a2 < 0)
        {
            return 1.0;
        }
        if (!(J > 0))
        {
            return J;
        }
        const double fSize = J < 1 ? J : 1.0/J;   // no 1/J overflow
        const double fShape = 3.0*std::cbrt(J*J)/a2;
        switch (metric)
        {
            case TetQuality::Metric::size: return fSize;
            case TetQuality::Metric::shape: return fShape;
            default: return std::sqrt(fSize)*fShape;
        }
    }

    //- Where rankKey neither underflows to 0/0 nor overflows (a2 >=
    //  3 J^(2/3) > 3e-20 for J > 1e-30: the bound 1e-40 excludes round-off
    //  alone); elsewhere tetrahedra compare by their quality
    static inline bool keyRange(const double J, const double a2)
    {
        return J > 1e-30 && J < 1e30 && a2 > 1e-40 && a2 < 1e25;
    }

    static inline double rankKey(const double J, const double a2, const TetQuality::Metric metric)
    {
        // q^6 (sizeShape: min(J, 1/J)^3 729 J^4/a2^6), q^3 (shape), q (size)
        switch (metric)
        {
            case TetQuality::Metric::size: return std::min(J, 1.0/J);
            case TetQuality::Metric::shape: return 27.0*J*J/(a2*a2*a2);
            default:
            {
                const double a6 = a2*a2*a2;
                const double J4 = (J*J)*(J*J);
                return 729.0*(J < 1 ? J4*(J*J*J) : J)/(a6*a6);
            }
        }
    }

    //- The worst of a cell's tetrahedra, from their J and |A|_F^2: ranked by
    //  rankKey where it neither underflows nor overflows, else (inverted,
    //  degenerate, extreme) by the quality itself; quality() takes one cbrt
    class Worst
    {
        TetQuality::Metric metric_;
        double qOther_ = 1e308, bestKey_ = 1e308, bestJ_ = 1, bestA2_ = 3;
        bool keyed_ = false;


    public:
        explicit Worst(TetQuality::Metric metric) : metric_(metric) {}

        //- As kept elsewhere (PrismBatch's lanes): the ranked worst (if
        //  ranked) and the least quality of the others
        Worst
        (
            TetQuality::Metric metric,
            double J,
            double a2,
            bool ranked,
            double other
        )
        :
            metric_(metric),
            qOther_(other),
            bestJ_(J),
            bestA2_(a2),
            keyed_(ranked)
        {}

        inline void add(const double J, const double a2)
        {
            add(J, a2, keyRange(J, a2) ? rankKey(J, a2, metric_) : 0);
        }

        //- Add with its key computed already (rankKey, or 0: rank by the
        //  quality)
        inline void add(const double J, const double a2, const double key)
        {
            if (key > 1e-250 && key < 1e250)
            {
                if (key < bestKey_)
                {
                    bestKey_ = key;
                    bestJ_ = J;
                    bestA2_ = a2;
                    keyed_ = true;
                }
            }
            else
            {
                qOther_ = std::min(qOther_, TetMeasures::quality(J, a2, metric_));
            }
        }

        //- Was a tetrahedron ranked by its key? The ranked worst's J and
        //  |A|^2; the least quality of the others (1e308 if none)
        bool ranked() const { return keyed_; }
        double J() const { return bestJ_; }
        double a2() const { return bestA2_; }
        double other() const { return qOther_; }

        //- The worst quality added (1e308 if none)
        inline double quality() const
        {
            return keyed_
                ? std::min(qOther_, TetMeasures::quality(bestJ_, bestA2_, metric_))
                : qOther_;
        }
    };

    static inline double tetQuality
    (
        const double* r0, const double* r1, const double* r2, const double* r3,
        const double* c0, const double* c1, const double* c2, const double* c3,
        TetQuality::Metric metric
    )
    {
        double J, a2;
        measures(r0, r1, r2, r3, c0, c1, c2, c3, J, a2);
        return quality(J, a2, metric);
    }
};

} // namespace detail
} // namespace dcprbf
