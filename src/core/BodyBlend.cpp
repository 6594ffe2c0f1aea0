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
    outer_(centres.size(), std::numeric_limits<double>::infinity())
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
            const double r = (x.row(i).transpose() - centres_[b]).norm();
            double s = 0;
            if (r <= inner_[b] || std::isinf(outer_[b]))
            {
                s = 1;  // inside, or nothing static: the body's motion
            }
            else if (r < outer_[b])
            {
                s = std::log(outer_[b]/r)/std::log(outer_[b]/inner_[b]);
            }
            w(i, b) = s;
            sum += s;
        }
        if (sum > 1)
        {
            w.row(i) /= sum;
        }
    }
    return w;
}

} // namespace dcprbf
