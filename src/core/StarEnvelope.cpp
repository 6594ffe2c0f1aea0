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


void StarEnvelope::radii(const Eigen::Vector3d& x, double& lnInner, double& lnOuter) const
{
    const Eigen::Vector3d u((x - centre_).normalized());

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

} // namespace dcprbf
