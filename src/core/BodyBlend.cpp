// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "BodyBlend.hpp"

#include <cmath>
#include <limits>

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
    cumulative_(centres.size())
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
        if (!(outer_[b] > inner_[b]))
        {
            throw Error("BodyBlend: body " + std::to_string(b)
                + ": a static or another body's point is " + std::to_string(outer_[b])
                + " from its centre, inside the body's own extent "
                + std::to_string(inner_[b]) + ": no room to blend its rotation"
                " (move the centre, or leave the body out of the rotation)");
        }
    }
}


double BodyBlend::profile(int b, double r) const
{
    if (r <= inner_[b] || std::isinf(outer_[b]))
    {
        return 1;   // inside, or nothing static: the body's motion
    }
    if (r >= outer_[b])
    {
        return 0;
    }
    const std::vector<double>& F = cumulative_[b];
    if (F.empty())
    {
        return std::log(outer_[b]/r)/std::log(outer_[b]/inner_[b]);
    }
    const double t = (r - inner_[b])/(outer_[b] - inner_[b])*double(F.size() - 1);
    const std::size_t k = std::min(std::size_t(t), F.size() - 2);
    const double f = t - double(k);
    return 1 - ((1 - f)*F[k] + f*F[k + 1]);
}


Eigen::MatrixXd BodyBlend::weights(const Points& x) const
{
    const Eigen::Index n = x.rows();
    const int nb = int(centres_.size());
    Eigen::MatrixXd w(n, nb);

    #pragma omp parallel for schedule(static)
    for (Eigen::Index i = 0; i < n; ++i)
    {
        double sum = 0;
        for (int b = 0; b < nb; ++b)
        {
            w(i, b) = profile(b, (x.row(i).transpose() - centres_[b]).norm());
            sum += w(i, b);
        }
        if (sum > 1)
        {
            w.row(i) /= sum;
        }
    }
    return w;
}


void BodyBlend::setDensity(int body, const std::vector<double>& density)
{
    if (body < 0 || body >= int(centres_.size()))
    {
        throw Error("BodyBlend::setDensity: no body " + std::to_string(body));
    }
    if (density.empty())
    {
        throw Error("BodyBlend::setDensity: empty density");
    }
    std::vector<double> F(density.size() + 1, 0.0);
    for (std::size_t k = 0; k < density.size(); ++k)
    {
        if (!(density[k] > 0) || !std::isfinite(density[k]))
        {
            throw Error("BodyBlend::setDensity: density " + std::to_string(density[k])
                + " in bin " + std::to_string(k) + " (must be positive)");
        }
        F[k + 1] = F[k] + density[k];
    }
    for (double& f : F)
    {
        f /= F.back();
    }
    cumulative_[body] = std::move(F);
}


std::vector<double> BodyBlend::cellAdaptedDensity(const std::vector<double>& cellExtent)
{
    std::vector<double> h(cellExtent);
    // bins without a cell: the nearest bin's extent (forward, then backward)
    for (std::size_t k = 1; k < h.size(); ++k)
    {
        if (!(h[k] > 0)) h[k] = h[k - 1];
    }
    for (std::size_t k = h.size(); k-- > 1;)
    {
        if (!(h[k - 1] > 0)) h[k - 1] = h[k];
    }
    std::vector<double> density(h.size(), 1.0);
    for (std::size_t k = 0; k < h.size(); ++k)
    {
        if (h[k] > 0) density[k] = 1/h[k];
    }
    return density;
}

} // namespace dcprbf
