// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: direction-dependent inner and outer radii of the
// ring between a moving body and the rest of the boundary, seen from the
// body's centre c, with a bounded angular slope.
//
// For a unit direction u:
//     ln R_in(u)  = max over the body's points b  of ln|b - c| - kappa angle(u, b - c)
//     ln R_out(u) = min over the other points p   of ln|p - c| + kappa angle(u, p - c)
// R_in covers the body (R_in(u) >= |b - c| in the direction of every body
// point b), R_out stays inside the walls, and both change by at most a
// factor exp(kappa dphi) over an angle dphi: a blend that falls from 1 at
// R_in to 0 at R_out linearly in ln r has |ds/dphi| <= kappa / ln(R_out /
// R_in), so the rotation map x -> c + R(a s(x))(x - c), whose Jacobian is
// 1 + a ds/dphi, stays valid in the continuum up to a = ln(R_out/R_in)/kappa,
// while the ring is as wide as the geometry allows in every direction (a
// thin body turns rigidly only close to itself; a far wall leaves room).
// kappa = 0 gives the radial ring R_in = max |b - c|, R_out = min |p - c|.
//
// Exact: every point is compared with every boundary point, pruned by
// sorting (the candidates that can still win); the cost is at most
// n x (body + other points), once. For large 3D meshes buildGrid() first
// evaluates both radii exactly at the nodes of a latitude-longitude grid of
// directions; a point then takes the tightest bounds its cell's four nodes
// give through the slope: ln R_in(u) <= ln R_in(g) + kappa angle(u, g) and
// ln R_out(u) >= ln R_out(g) - kappa angle(u, g) (both radii have slope
// <= kappa), so the ring is never wider than the exact one (the body still
// turns rigidly, the walls still stay) and narrower by at most
// 2 kappa x the grid spacing in ln r.
#pragma once

#include "Types.hpp"

#include <vector>

namespace dcprbf
{

class StarEnvelope
{
public:

    //- centre c; body: the body's points; others: the static points and
    //  the other bodies' points (may be empty: R_out infinite); kappa >= 0
    StarEnvelope
    (
        const Eigen::Vector3d& centre,
        const Points& body,
        const Points& others,
        double kappa
    );

    //- ln R_in and ln R_out in the direction of x from the centre (x not
    //  at the centre); lnOuter is +infinity without other points
    void radii(const Eigen::Vector3d& x, double& lnInner, double& lnOuter) const;

    //- The exact radii (what radii() returns without a grid)
    void exactRadii(const Eigen::Vector3d& u, double& lnInner, double& lnOuter) const;

    //- Evaluate the radii at a grid of nPolar + 1 polar angles x
    //  2 nPolar azimuths (threaded); radii() then bounds from it
    void buildGrid(int nPolar);

private:

    struct Ray
    {
        Eigen::Vector3d dir;    // unit direction from the centre
        double lnR;             // ln of the distance
    };

    //- Rays of points, sorted by lnR (descending: body, ascending: others)
    static std::vector<Ray> rays
    (
        const Eigen::Vector3d& c,
        const Points& p,
        bool descending
    );

    //- Unit direction of grid node (i polar, j azimuth)
    Eigen::Vector3d node(int i, int j) const;

    Eigen::Vector3d centre_;
    double kappa_;
    std::vector<Ray> body_;
    std::vector<Ray> others_;

    //- The grid (empty: exact): polar intervals, radii at the nodes
    int nPolar_ = 0;
    std::vector<double> gridInner_;
    std::vector<double> gridOuter_;
};

} // namespace dcprbf
