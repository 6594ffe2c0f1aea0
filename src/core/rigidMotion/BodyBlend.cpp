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
        if (r == 0)
        {
            return 1;
        }
        double lnIn, lnOut;
        stars_[b]->radii(x, lnIn, lnOut);
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
    checkRadialRoom(b);
    if (r >= outer_[b])
    {
        return 0;
    }
    return std::log(outer_[b]/r)/std::log(outer_[b]/inner_[b]);
}


void BodyBlend::setStar(int body, double kappa, double ramp, int gridPolar)
{
    if (body < 0 || body >= int(centres_.size()))
    {
        throw Error("BodyBlend::setStar: no body " + std::to_string(body));
    }
    if (!(ramp >= 0 && ramp <= 1))
    {
        throw Error("BodyBlend::setStar: ramp must be in [0, 1], got " + std::to_string(ramp));
    }
    Eigen::Index nb = 0;
    for (const int o : bodyOf_) nb += (o == body);
    Points own(nb, 3), others(boundary_.rows() - nb, 3);
    Eigen::Index i = 0, j = 0;
    for (Eigen::Index k = 0; k < boundary_.rows(); ++k)
    {
        if (bodyOf_[k] == body) own.row(i++) = boundary_.row(k);
        else others.row(j++) = boundary_.row(k);
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
