// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "BodyBlend.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace dcprbf
{

BodyBlend::BodyBlend
(
    const Points& boundary,
    const std::vector<int>& bodyOf,
    const std::vector<Eigen::Vector3d>& centres
)
:
    centres_(centres),
    inner_(centres.size(), -1),
    outer_(centres.size(), std::numeric_limits<double>::infinity()),
    stars_(centres.size()),
    ramps_(centres.size(), 0.0),
    hingeAxes_(centres.size(), Eigen::Vector3d::Zero()),
    hingeSides_(centres.size(), Eigen::Vector3d::Zero()),
    boundary_(boundary),
    bodyOf_(bodyOf)
{
    const int nb = int(centres.size());
    if (Eigen::Index(bodyOf.size()) != boundary.rows())
    {
        throw Error("BodyBlend: " + std::to_string(bodyOf.size())
            + " body labels for " + std::to_string(boundary.rows()) + " points");
    }
    for (Eigen::Index i = 0; i < boundary.rows(); ++i)
    {
        if (bodyOf[i] < -1 || bodyOf[i] >= nb)
        {
            throw Error("BodyBlend: body label " + std::to_string(bodyOf[i])
                + " out of range [-1, " + std::to_string(nb) + ")");
        }
        for (int b = 0; b < nb; ++b)
        {
            const double r = (boundary.row(i).transpose() - centres[b]).norm();
            if (bodyOf[i] == b)
            {
                inner_[b] = std::max(inner_[b], r);
            }
            else
            {
                outer_[b] = std::min(outer_[b], r);
            }
        }
    }
    for (int b = 0; b < nb; ++b)
    {
        if (inner_[b] < 0)
        {
            throw Error("BodyBlend: body " + std::to_string(b) + " has no points");
        }
    }
}


void BodyBlend::checkRadialRoom(int b) const
{
    if (!(outer_[b] > inner_[b]))
    {
        throw Error("BodyBlend: body " + std::to_string(b)
            + ": a static or another body's point is " + std::to_string(outer_[b])
            + " from its centre, inside the body's own extent "
            + std::to_string(inner_[b]) + ": no room to blend its rotation"
            " radially");
    }
}


double BodyBlend::ramped(double t, double ramp)
{
    if (ramp <= 0 || t <= 1 - ramp)
    {
        return t/(1 - ramp/2);
    }
    // slope smoothstep((1 - t)/ramp): its integral G(v) = v^3 - v^4/2
    const double v = (1 - t)/ramp;
    return ((1 - ramp) + ramp*(0.5 - (v*v*v - 0.5*v*v*v*v)))/(1 - ramp/2);
}


double BodyBlend::profile(int b, const Eigen::Vector3d& x) const
{
    const double r = (x - centres_[b]).norm();
    if (r <= inner_[b] && !stars_[b])
    {
        checkRadialRoom(b);
        return 1;
    }
    if (std::isinf(outer_[b]))
    {
        return 1;   // nothing static: the body's motion
    }
    if (stars_[b])
    {
        const double w = r == 0 ? 1 : starProfile(b, x, r);
        return hingeAxes_[b].isZero() ? w : w*hingeFactor(b, x);
    }
    checkRadialRoom(b);
    if (r >= outer_[b])
    {
        return 0;
    }
    return std::log(outer_[b]/r)/std::log(outer_[b]/inner_[b]);
}


double BodyBlend::starProfile(int b, const Eigen::Vector3d& x, double r) const
{
    double lnIn, lnOut;
    stars_[b]->radii(x, lnIn, lnOut);
    if (std::isinf(lnOut))
    {
        return 1;   // nothing static beyond the partner: the body's motion
    }
    if (!(lnOut > lnIn))
    {
        throw Error("BodyBlend: body " + std::to_string(b)
            + ": no room between the body and the static boundary in the"
            " direction of a point at distance " + std::to_string(r)
            + " from its centre");
    }
    const double t = (lnOut - std::log(r))/(lnOut - lnIn);
    return t >= 1 ? 1 : t <= 0 ? 0 : ramped(t, ramps_[b]);
}


double BodyBlend::hingeFactor(int b, const Eigen::Vector3d& x) const
{
    const Eigen::Vector3d& e = hingeAxes_[b];
    const Eigen::Vector3d d(x - centres_[b]);
    const Eigen::Vector3d v(d - e*e.dot(d));
    const double n = v.norm();
    return n > 0 ? 0.5*(1 + v.dot(hingeSides_[b])/n) : 0.5;
}


void BodyBlend::setStar(int body, double kappa, double ramp, int gridPolar)
{
    buildStar(body, kappa, ramp, gridPolar, {});
}


void BodyBlend::setHinge
(
    int body,
    const Eigen::Vector3d& axis,
    const std::vector<bool>& partner,
    double kappa,
    double ramp,
    int gridPolar
)
{
    if (Eigen::Index(partner.size()) != boundary_.rows())
    {
        throw Error("BodyBlend::setHinge: " + std::to_string(partner.size())
            + " partner marks for " + std::to_string(boundary_.rows()) + " points");
    }
    if (!(axis.norm() > 0))
    {
        throw Error("BodyBlend::setHinge: zero axis");
    }
    const Eigen::Vector3d e(axis.normalized());
    Eigen::Vector3d centroid(Eigen::Vector3d::Zero());
    Eigen::Index n = 0;
    double extent = 0;
    for (Eigen::Index k = 0; k < boundary_.rows(); ++k)
    {
        if (partner[k] && bodyOf_[k] != -1)
        {
            throw Error("BodyBlend::setHinge: point " + std::to_string(k)
                + " is marked as the hinge's partner but belongs to body "
                + std::to_string(bodyOf_[k]));
        }
        if (bodyOf_[k] == body)
        {
            const Eigen::Vector3d p(boundary_.row(k).transpose());
            centroid += p;
            extent = std::max(extent, (p - centres_[body]).norm());
            ++n;
        }
    }
    buildStar(body, kappa, ramp, gridPolar, partner);
    const Eigen::Vector3d d(centroid/double(n) - centres_[body]);
    const Eigen::Vector3d side(d - e*e.dot(d));
    if (!(side.norm() > 1e-9*extent))
    {
        throw Error("BodyBlend::setHinge: body " + std::to_string(body)
            + ": the centroid of its points lies on its hinge axis: no side"
            " to turn");
    }
    hingeAxes_[body] = e;
    hingeSides_[body] = side.normalized();
}


void BodyBlend::buildStar
(
    int body,
    double kappa,
    double ramp,
    int gridPolar,
    const std::vector<bool>& skip
)
{
    if (body < 0 || body >= int(centres_.size()))
    {
        throw Error("BodyBlend::setStar: no body " + std::to_string(body));
    }
    if (!(ramp >= 0 && ramp <= 1))
    {
        throw Error("BodyBlend::setStar: ramp must be in [0, 1], got " + std::to_string(ramp));
    }
    Eigen::Index nb = 0, ns = 0;
    for (Eigen::Index k = 0; k < boundary_.rows(); ++k)
    {
        nb += (bodyOf_[k] == body);
        ns += (!skip.empty() && skip[k]);
    }
    Points own(nb, 3), others(boundary_.rows() - nb - ns, 3);
    Eigen::Index i = 0, j = 0;
    for (Eigen::Index k = 0; k < boundary_.rows(); ++k)
    {
        if (bodyOf_[k] == body) own.row(i++) = boundary_.row(k);
        else if (skip.empty() || !skip[k]) others.row(j++) = boundary_.row(k);
    }
    auto star = std::make_shared<StarEnvelope>(centres_[body], own, others, kappa);
    if (gridPolar > 0)
    {
        star->buildGrid(gridPolar);
    }
    stars_[body] = star;
    ramps_[body] = ramp;
}


Eigen::MatrixXd BodyBlend::weights(const Points& x) const
{
    const Eigen::Index n = x.rows();
    const int nb = int(centres_.size());
    Eigen::MatrixXd w(n, nb);

    std::string error;
    #pragma omp parallel for schedule(dynamic, 256)
    for (Eigen::Index i = 0; i < n; ++i)
    {
        double sum = 0;
        try
        {
            for (int b = 0; b < nb; ++b)
            {
                w(i, b) = profile(b, x.row(i).transpose());
                sum += w(i, b);
            }
        }
        catch (const Error& e)
        {
            #pragma omp critical(dcprbfBodyBlend)
            error = e.what();
        }
        if (sum > 1)
        {
            w.row(i) /= sum;
        }
    }
    if (!error.empty())
    {
        throw Error(error);
    }
    return w;
}


} // namespace dcprbf
