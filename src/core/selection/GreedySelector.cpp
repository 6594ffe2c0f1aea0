// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "GreedySelector.hpp"
#include "IncrementalGreedyModel.hpp"
#include "PointSetChecks.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace dcprbf
{

namespace
{
//- Index of the largest value among the unselected candidates with
//  allowed(i), ties to the lowest index; -1 if none
template<class Allowed>
Eigen::Index argmax
(
    const Eigen::VectorXd& v,
    const std::vector<char>& selected,
    Allowed allowed
)
{
    Eigen::Index best = -1;
    for (Eigen::Index i = 0; i < v.size(); ++i)
    {
        if (!selected[i] && allowed(i) && (best < 0 || v(i) > v(best))) best = i;
    }
    return best;
}
}


GreedySelector::GreedySelector
(
    const RadialKernel& kernel,
    bool polynomial,
    int dim,
    const GreedyOptions& options
)
:
    kernel_(kernel),
    polynomial_(polynomial),
    dim_(dim),
    options_(options)
{
    const LinearPolynomial check(polynomial, dim);  // throws for a bad dim
    if (kernel.needsPolynomial() && !polynomial)
    {
        throw Error("the " + kernel.name() + " kernel needs the linear polynomial");
    }
    std::ostringstream os;
    const GreedyOptions& o = options_;
    const Eigen::Index seedSize =
        o.seed.empty() ? (polynomial ? dim + 1 : 1) : Eigen::Index(o.seed.size());
    if (!(o.tolerance > 0) || !std::isfinite(o.tolerance))
    {
        os << "greedy tolerance must be positive and finite, got " << o.tolerance;
    }
    else if (o.minPoints < 0 || o.maxPoints < 1)
    {
        os  << "greedy minPoints must be >= 0 and maxPoints >= 1, got "
            << o.minPoints << " and " << o.maxPoints;
    }
    else if (o.maxPoints < o.minPoints)
    {
        os  << "greedy maxPoints (" << o.maxPoints << ") is below minPoints ("
            << o.minPoints << ")";
    }
    else if (o.maxPoints < seedSize)
    {
        os  << "greedy maxPoints (" << o.maxPoints << ") is below the seed size ("
            << seedSize << ")";
    }
    if (!os.str().empty()) throw Error(os.str());
}


void GreedySelector::checkInput
(
    const Points& x,
    const Values& d
) const
{
    if (d.rows() != x.rows())
    {
        throw Error
        (
            "greedy selection: " + std::to_string(d.rows()) + " displacements"
            " for " + std::to_string(x.rows()) + " candidate points"
        );
    }
    const Eigen::Index need = std::max<Eigen::Index>
    (
        {options_.minPoints, Eigen::Index(options_.seed.size()),
         PointSetChecks::minimumSize(LinearPolynomial(polynomial_, dim_))}
    );
    if (x.rows() < need)
    {
        throw Error
        (
            "greedy selection: " + std::to_string(x.rows()) + " candidate"
            " points are too few, " + std::to_string(need) + " are needed"
        );
    }
    PointSetChecks::checkCoordinates(x, dim_, "candidate point");
    if (!d.allFinite())
    {
        throw Error("greedy selection: displacements are not finite");
    }
    PointSetChecks::checkDistinct(x, "candidate point");
}


std::vector<Eigen::Index> GreedySelector::seed
(
    const Points& x,
    const Values& d
) const
{
    // the candidates' bounding-box frame: a check in raw coordinates fails for
    // sets far from the origin (terrain in UTM coordinates)
    const LinearPolynomial poly(LinearPolynomial::boundingBox(polynomial_, dim_, x));
    std::vector<Eigen::Index> s = options_.seed;
    if (s.empty())
    {
        const std::vector<char> none(x.rows(), 0);
        s.push_back(argmax(d.rowwise().squaredNorm(), none, [](Eigen::Index)
        {
            return true;
        }));
        if (polynomial_)
        {
            // farthest point from the seed's affine hull, dim times
            for (int k = 0; k < dim_; ++k)
            {
                Points hull(s.size(), 3);
                for (std::size_t j = 0; j < s.size(); ++j) hull.row(j) = x.row(s[j]);
                // distance to the hull: remove the components along an
                // orthonormal basis of the hull's edge vectors
                const Eigen::RowVector3d o = hull.row(0);
                Eigen::MatrixXd rel = (x.rowwise() - o).transpose();
                if (hull.rows() > 1)
                {
                    const Eigen::MatrixXd B =
                        (hull.bottomRows(hull.rows() - 1).rowwise() - o).transpose();
                    const Eigen::MatrixXd Qb = B.householderQr().householderQ()
                        *Eigen::MatrixXd::Identity(3, B.cols());
                    rel -= Qb*(Qb.transpose()*rel);
                }
                std::vector<char> taken(x.rows(), 0);
                for (const Eigen::Index i : s) taken[i] = 1;
                s.push_back(argmax(rel.colwise().squaredNorm().transpose(), taken,
                    [](Eigen::Index) { return true; }));
            }
        }
    }
    std::set<Eigen::Index> distinct(s.begin(), s.end());
    if
    (
        distinct.size() != s.size() || *distinct.begin() < 0
     || *distinct.rbegin() >= x.rows()
    )
    {
        throw Error("greedy seed indices must be distinct candidate indices");
    }
    Points hull(s.size(), 3);
    for (std::size_t j = 0; j < s.size(); ++j) hull.row(j) = x.row(s[j]);
    try
    {
        poly.checkUnisolvent(hull);
    }
    catch (const Error& e)
    {
        throw Error(std::string("greedy seed: ") + e.what());
    }
    return s;
}


GreedyResult GreedySelector::select(const Points& x, const Values& d) const
{
    return run
    (
        [](const RadialKernel& kernel, const LinearPolynomial& frame,
           const Points& candidates, const Values& displacements)
        {
            return std::unique_ptr<GreedyModel>
            (
                new IncrementalGreedyModel(kernel, frame, candidates, displacements)
            );
        },
        x,
        d
    );
}


GreedyResult GreedySelector::run
(
    const ModelFactory& makeModel,
    const Points& x,
    const Values& d
) const
{
    checkInput(x, d);
    const LinearPolynomial frame = LinearPolynomial::boundingBox(polynomial_, dim_, x);
    GreedyResult result(frame);
    const std::unique_ptr<GreedyModel> model = makeModel(kernel_, frame, x, d);
    iterate(*model, seed(x, d), d, result);
    result.factorization = model->releaseFactorization();
    for (std::size_t j = 0; j < result.selected.size(); ++j)
    {
        result.centres.row(j) = x.row(result.selected[j]);
    }
    return result;
}


void GreedySelector::iterate
(
    GreedyModel& model,
    const std::vector<Eigen::Index>& seed,
    const Values& d,
    GreedyResult& result
) const
{
    const Eigen::Index nb = d.rows();
    const Eigen::Index minPoints = std::max<Eigen::Index>(options_.minPoints, seed.size());
    const double scale = std::sqrt(d.rowwise().squaredNorm().maxCoeff());
    result.maxDisplacement = scale;
    std::vector<char> selected(nb, 0);
    std::vector<Eigen::Index> next = seed;
    for (bool seeding = true; ; seeding = false)
    {
        // The seed at once (a dependent seed is an error); then one point
        // at a time: one numerically dependent on those selected ends the
        // selection (the model is unchanged by the refused point)
        std::vector<Eigen::Index> added;
        if (seeding)
        {
            model.add(next);
            added = next;
        }
        else
        {
            for (const Eigen::Index i : next)
            {
                try
                {
                    model.add({i});
                }
                catch (const Error&)
                {
                    result.dependent = true;
                    break;
                }
                added.push_back(i);
            }
        }
        if (added.empty())
        {
            break;
        }
        for (const Eigen::Index i : added)
        {
            selected[i] = 1;
            result.selected.push_back(i);
        }
        const Eigen::Index n = result.selected.size();
        const Values& e = model.residual();
        const Eigen::VectorXd err2 = e.rowwise().squaredNorm();
        const Eigen::Index worst = argmax(err2, selected, [](Eigen::Index) { return true; });
        const double eps =
            worst < 0 || scale == 0 ? 0.0 : std::sqrt(err2(worst))/scale;
        result.historySize.push_back(n);
        result.historyError.push_back(eps);
        result.converged = eps <= options_.tolerance;
        if
        (
            (result.converged && n >= minPoints) || n >= options_.maxPoints
         || worst < 0 || result.dependent
        )
        {
            break;
        }
        next.assign(1, worst);
        if (options_.doubleEdged && n + 2 <= options_.maxPoints)
        {
            const Eigen::RowVector3d ew = e.row(worst);
            const Eigen::Index other = argmax(err2, selected, [&](Eigen::Index i)
            {
                return i != worst && e.row(i).dot(ew) < 0;
            });
            if (other >= 0) next.push_back(other);
        }
    }
    model.coefficients(result.alpha, result.beta);
    result.centres.resize(result.selected.size(), 3);
}

} // namespace dcprbf
