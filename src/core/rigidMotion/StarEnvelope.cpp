// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "StarEnvelope.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dcprbf
{

namespace
{

//- Angle between unit vectors (accurate near 0 and pi)
double angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

} // namespace


std::vector<StarEnvelope::Ray> StarEnvelope::rays
(
    const Eigen::Vector3d& c,
    const Points& p,
    bool descending
)
{
    std::vector<Ray> r;
    r.reserve(p.rows());
    for (Eigen::Index i = 0; i < p.rows(); ++i)
    {
        const Eigen::Vector3d d(p.row(i).transpose() - c);
        const double len = d.norm();
        if (len > 0)
        {
            r.push_back({d/len, std::log(len)});
        }
    }
    std::sort(r.begin(), r.end(), [descending](const Ray& a, const Ray& b)
    {
        return descending ? a.lnR > b.lnR : a.lnR < b.lnR;
    });
    return r;
}


StarEnvelope::StarEnvelope
(
    const Eigen::Vector3d& centre,
    const Points& body,
    const Points& others,
    double kappa
)
:
    centre_(centre),
    kappa_(kappa),
    body_(rays(centre, body, true)),
    others_(rays(centre, others, false))
{
    if (!(kappa >= 0))
    {
        throw Error("StarEnvelope: kappa must be >= 0, got " + std::to_string(kappa));
    }
    if (body_.empty())
    {
        throw Error("StarEnvelope: the body has no point away from its centre");
    }
}


void StarEnvelope::exactRadii
(
    const Eigen::Vector3d& u,
    double& lnInner,
    double& lnOuter
) const
{
    // max of lnR - kappa angle: a ray with lnR below the best cannot win
    lnInner = -std::numeric_limits<double>::infinity();
    for (const Ray& r : body_)
    {
        if (r.lnR <= lnInner) break;
        lnInner = std::max(lnInner, r.lnR - kappa_*angle(u, r.dir));
    }

    // min of lnR + kappa angle: a ray with lnR above the best cannot win
    lnOuter = std::numeric_limits<double>::infinity();
    for (const Ray& r : others_)
    {
        if (r.lnR >= lnOuter) break;
        lnOuter = std::min(lnOuter, r.lnR + kappa_*angle(u, r.dir));
    }
}


Eigen::Vector3d StarEnvelope::node(int i, int j) const
{
    const double pi = EIGEN_PI;
    const double theta = pi*i/nPolar_, phi = pi*j/nPolar_;
    return Eigen::Vector3d
    (
        std::sin(theta)*std::cos(phi), std::sin(theta)*std::sin(phi), std::cos(theta)
    );
}


void StarEnvelope::buildGrid(int nPolar)
{
    if (nPolar < 2)
    {
        throw Error("StarEnvelope::buildGrid: at least 2 polar intervals");
    }
    nPolar_ = nPolar;
    const int nAz = 2*nPolar, n = (nPolar + 1)*nAz;
    gridInner_.assign(n, 0.0);
    gridOuter_.assign(n, 0.0);
    #pragma omp parallel for schedule(dynamic, 16)
    for (int k = 0; k < n; ++k)
    {
        exactRadii(node(k/nAz, k % nAz), gridInner_[k], gridOuter_[k]);
    }
}


void StarEnvelope::radii(const Eigen::Vector3d& x, double& lnInner, double& lnOuter) const
{
    const Eigen::Vector3d u((x - centre_).normalized());
    if (!nPolar_)
    {
        exactRadii(u, lnInner, lnOuter);
        return;
    }
    const double pi = EIGEN_PI;
    const int nAz = 2*nPolar_;
    const double theta = std::acos(std::max(-1.0, std::min(1.0, u.z())));
    double phi = std::atan2(u.y(), u.x());
    if (phi < 0) phi += 2*pi;
    const int i = std::min(nPolar_ - 1, int(theta/pi*nPolar_));
    const int j = std::min(nAz - 1, int(phi/pi*nPolar_));
    lnInner = std::numeric_limits<double>::infinity();
    lnOuter = -std::numeric_limits<double>::infinity();
    for (const int di : {0, 1})
    {
        for (const int dj : {0, 1})
        {
            const int jj = (j + dj) % nAz, k = (i + di)*nAz + jj;
            const double a = kappa_*angle(u, node(i + di, jj));
            lnInner = std::min(lnInner, gridInner_[k] + a);
            lnOuter = std::max(lnOuter, gridOuter_[k] - a);
        }
    }
}

} // namespace dcprbf
