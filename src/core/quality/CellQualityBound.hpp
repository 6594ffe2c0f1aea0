// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: a lower bound of a cell's quality (the worst
// TetQuality of its decomposition into tetrahedra, as CellQualityScan
// measures it) at a fraction of its cost, from the affine map that best
// fits the cell's motion.
//
// The vertices' motion is fitted by an affine map, X -> T X + t (least
// squares); r is the largest distance of a vertex from where T puts it. The
// decomposition's points (face and cell centres) are averages of vertices,
// so each tetrahedron's current edges are G = T E + R with E its reference
// edges and every column of R at most 2 r long: its A = G E^-1 (TetQuality)
// is T + R E^-1, within eps = 2 sqrt(3) r kappa of T in the 2-norm, kappa
// the largest |E^-1|_2 of the cell's tetrahedra (reference only, set up
// once). Every matrix that close to T has J = det >= det T (1 - eps/s)^3,
// with s <= the least singular value of T (T^T T's least eigenvalue from
// below, Newton steps on its characteristic polynomial), J <= det T
// (1 + eps/s)^3 and |A|_F <= |T|_F + sqrt(3) eps; each factor of the
// quality is then bounded below at the worst of them (min(J, 1/J) by
// min(Jlo, 1/Jhi), J^(2/3)/|A|_F^2 by Jlo^(2/3)/(|T|_F + sqrt(3) eps)^2). A
// cell moved rigidly or affinely (r = 0) is bounded by its exact quality; a
// cell whose fit is too poor (eps >= s) or that T inverts has no bound
// (-infinity): it must be measured. The bound is lowered by a relative
// 1e-12 and the residual raised by the round-off of the coordinates, so
// that it holds for computed values too.
#pragma once

#include "TetQuality.hpp"

#include <cstddef>
#include <limits>

namespace dcprbf
{

class CellQualityBound
{
public:
    //- Set up from the cell's nv vertices (reference coordinates x y z at
    //  x0 + 3 v[k]) and kappa (the largest |E^-1|_2 of its tetrahedra;
    //  infinity: never bounded)
    CellQualityBound(const double* x0, const int* v, int nv, double kappa);

    //- Not bounded (always measured)
    CellQualityBound() = default;

    //- The cell's lower bound for the current points x (x y z at
    //  x + 3 v[k], the same v) under metric m (-infinity: none)
    double lower(const double* x0, const double* x, const int* v, int nv, TetQuality::Metric m) const;

    //- The bound from the fitted map's J = det T, F2 = |T|_F^2, s <= its
    //  least singular value, and eps (-infinity: none)
    static double fromMap(double J, double F2, double s, double eps, TetQuality::Metric m);

    //- |E^-1|_2 of the tetrahedron with reference edges e0 e1 e2 (from its
    //  first vertex), from above: to round-off for a well-conditioned E,
    //  at most |E^-1|_F; infinity if degenerate (TetMeasures' test)
    static double inverseNorm(const double* e0, const double* e1, const double* e2);

    //- Is the cell bounded at all?
    bool bounded() const { return kappa_ < std::numeric_limits<double>::infinity(); }

private:
    //- The inverse of the reference moment matrix sum (X - Xm)(X - Xm)^T,
    //  symmetric: xx xy xz yy yz zz
    double minv_[6] = {0, 0, 0, 0, 0, 0};

    //- The largest |E^-1|_2 of the cell's tetrahedra
    double kappa_ = std::numeric_limits<double>::infinity();
};

} // namespace dcprbf
