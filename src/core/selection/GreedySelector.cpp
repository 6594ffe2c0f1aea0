// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "GreedySelector.hpp"
#include "IncrementalGreedyModel.hpp"
#include "CandidateRows.hpp"
#include "PointSetChecks.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

namespace dcprbf
{

namespace
{
//- Local index of the largest value among this rank's unselected candidates
//  with allowed(i), ties to the lowest index; -1 if none
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

//- The global best of v over the ranks' unselected candidates with
//  allowed(i) (a global index, -1 if none; CandidateRows::argmax)
template<class Allowed>
CandidateRows::Best globalArgmax
(
    const CandidateRows& rows,
    const Eigen::VectorXd& v,
    const std::vector<char>& selected,
    Allowed allowed
)
{
    const Eigen::Index i = argmax(v, selected, allowed);
    return rows.argmax(i >= 0 ? v(i) : 0.0, i);
}

bool all(Eigen::Index) { return true; }

//- |v_i|^2 per row, each row on its own (the same value whatever block of
//  rows a rank holds)
Eigen::VectorXd squaredNorms(const Values& v)
{
    Eigen::VectorXd n(v.rows());
    for (Eigen::Index i = 0; i < v.rows(); ++i)
    {
        n(i) = v(i, 0)*v(i, 0) + v(i, 1)*v(i, 1) + v(i, 2)*v(i, 2);
    }
    return n;
}

//- The frame of all ranks' candidates' bounding box (the same frame as
//  LinearPolynomial::boundingBox of the whole set)
LinearPolynomial boxFrame(bool polynomial, int dim, const CandidateRows& rows)
{
    const double inf = std::numeric_limits<double>::infinity();
    const Points& x = rows.points();
    // the maxima of x and of -x
    double box[6] = {-inf, -inf, -inf, -inf, -inf, -inf};
    for (Eigen::Index i = 0; i < x.rows(); ++i)
    {
        for (int k = 0; k < 3; ++k)
        {
            box[k] = std::max(box[k], x(i, k));
            box[3 + k] = std::max(box[3 + k], -x(i, k));
        }
    }
    rows.comm().max(box, 6);
    if (!(box[0] > -inf))
    {
        return LinearPolynomial(polynomial, dim);
    }
    Points corners(2, 3);
    corners << -box[3], -box[4], -box[5], box[0], box[1], box[2];
    return LinearPolynomial::boundingBox(polynomial, dim, corners);
}

//- Global candidate i's coordinates, on every rank
Eigen::RowVector3d coordinates(const CandidateRows& rows, Eigen::Index i)
{
    double out[6];
    rows.fetch(i, nullptr, 0, out);
    return Eigen::RowVector3d(out[0], out[1], out[2]);
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


void GreedySelector::checkInput(const CandidateRows& rows) const
{
    const Eigen::Index need = std::max<Eigen::Index>
    (
        {options_.minPoints, Eigen::Index(options_.seed.size()),
         PointSetChecks::minimumSize(LinearPolynomial(polynomial_, dim_))}
    );
    if (rows.total() < need)
    {
        throw Error
        (
            "greedy selection: " + std::to_string(rows.total()) + " candidate"
            " points are too few, " + std::to_string(need) + " are needed"
        );
    }
    // each rank its own block; the ranks agree before throwing (none is
    // left waiting in a collective call)
    std::string error;
    try
    {
        PointSetChecks::checkCoordinates(rows.points(), dim_, "candidate point");
        if (!rows.values().allFinite())
        {
            throw Error("greedy selection: displacements are not finite");
        }
        PointSetChecks::checkDistinct(rows.points(), "candidate point");
    }
    catch (const Error& e)
    {
        error = e.what();
    }
    if (rows.comm().any(!error.empty()))
    {
        throw Error
        (
            error.empty()
          ? "greedy selection: another rank's candidates are ill-posed" : error
        );
    }
}


std::vector<Eigen::Index> GreedySelector::seed
(
    const Points& x,
    const Values& d
) const
{
    return seed(CandidateRows(x, d));
}


std::vector<Eigen::Index> GreedySelector::seed(const CandidateRows& rows) const
{
    const Points& x = rows.points();
    std::vector<Eigen::Index> s = options_.seed;
    std::vector<Eigen::RowVector3d> hull;
    if (s.empty())
    {
        const std::vector<char> none(x.rows(), 0);
        s.push_back(globalArgmax(rows, squaredNorms(rows.values()), none, all).index);
        hull.push_back(coordinates(rows, s.back()));
        if (polynomial_)
        {
            // farthest point from the seed's affine hull, dim times
            std::vector<char> taken(x.rows(), 0);
            for (int k = 0; k < dim_; ++k)
            {
                const Eigen::Index l = rows.local(s.back());
                if (l >= 0) taken[l] = 1;
                // distance to the hull: remove the components along an
                // orthonormal basis of the hull's edge vectors, point by point
                const Eigen::RowVector3d o = hull[0];
                Eigen::MatrixXd Qb(3, 0);
                if (hull.size() > 1)
                {
                    Eigen::MatrixXd B(3, hull.size() - 1);
                    for (std::size_t j = 1; j < hull.size(); ++j)
                    {
                        B.col(j - 1) = (hull[j] - o).transpose();
                    }
                    Qb = B.householderQr().householderQ()
                        *Eigen::MatrixXd::Identity(3, B.cols());
                }
                Eigen::VectorXd dist2(x.rows());
                for (Eigen::Index i = 0; i < x.rows(); ++i)
                {
                    Eigen::Vector3d r = (x.row(i) - o).transpose();
                    for (Eigen::Index j = 0; j < Qb.cols(); ++j)
                    {
                        r -= Qb.col(j)*Qb.col(j).dot(r);
                    }
                    dist2(i) = r(0)*r(0) + r(1)*r(1) + r(2)*r(2);
                }
                s.push_back(globalArgmax(rows, dist2, taken, all).index);
                hull.push_back(coordinates(rows, s.back()));
            }
        }
    }
    std::set<Eigen::Index> distinct(s.begin(), s.end());
    if
    (
        distinct.size() != s.size() || *distinct.begin() < 0
     || *distinct.rbegin() >= rows.total()
    )
    {
        throw Error("greedy seed indices must be distinct candidate indices");
    }
    if (hull.empty())
    {
        for (const Eigen::Index i : s) hull.push_back(coordinates(rows, i));
    }
    Points h(s.size(), 3);
    for (std::size_t j = 0; j < s.size(); ++j) h.row(j) = hull[j];
    try
    {
        // in the candidates' bounding-box frame: a check in raw coordinates
        // fails for sets far from the origin (terrain in UTM coordinates)
        boxFrame(polynomial_, dim_, rows).checkUnisolvent(h);
    }
    catch (const Error& e)
    {
        throw Error(std::string("greedy seed: ") + e.what());
    }
    return s;
}


GreedyResult GreedySelector::select(const Points& x, const Values& d) const
{
    return select(CandidateRows(x, d));
}


GreedyResult GreedySelector::select(const CandidateRows& rows) const
{
    checkInput(rows);
    const LinearPolynomial frame = boxFrame(polynomial_, dim_, rows);
    GreedyResult result(frame);
    IncrementalGreedyModel model(kernel_, frame, rows);
    iterate(model, seed(rows), rows, result);
    result.factorization = model.releaseFactorization();
    result.centres = result.factorization->centres();
    return result;
}


GreedyResult GreedySelector::run
(
    const ModelFactory& makeModel,
    const Points& x,
    const Values& d
) const
{
    const CandidateRows rows(x, d);
    checkInput(rows);
    const LinearPolynomial frame = LinearPolynomial::boundingBox(polynomial_, dim_, x);
    GreedyResult result(frame);
    const std::unique_ptr<GreedyModel> model = makeModel(kernel_, frame, x, d);
    iterate(*model, seed(rows), rows, result);
    result.factorization = model->releaseFactorization();
    result.centres.resize(result.selected.size(), 3);
    for (std::size_t j = 0; j < result.selected.size(); ++j)
    {
        result.centres.row(j) = x.row(result.selected[j]);
    }
    return result;
}


namespace
{

//- The points next added to the model: the seed at once (a dependent seed
//  is an error); else one point at a time, one numerically dependent on
//  those selected ending the selection (result.dependent; the model is
//  unchanged by the refused point). The points added
std::vector<Eigen::Index> addToModel
(
    GreedyModel& model,
    const std::vector<Eigen::Index>& next,
    const bool seeding,
    GreedyResult& result
)
{
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
    return added;
}


//- The double-edged selection's second point: the worst unselected
//  candidate whose error e points against the worst one's (global index
//  worst; the error fetched from the rank holding it), -1 if none
Eigen::Index opposingWorst
(
    const CandidateRows& rows,
    const Values& e,
    const Eigen::VectorXd& err2,
    const std::vector<char>& selected,
    const Eigen::Index worst
)
{
    const Eigen::Index lw = rows.local(worst);
    const Eigen::RowVector3d own =
        lw >= 0 ? Eigen::RowVector3d(e.row(lw)) : Eigen::RowVector3d::Zero();
    double fetched[9];
    rows.fetch(worst, own.data(), 3, fetched);
    const Eigen::RowVector3d ew(fetched[6], fetched[7], fetched[8]);
    return globalArgmax(rows, err2, selected,
        [&](Eigen::Index i)
        {
            return i != lw && e.row(i).dot(ew) < 0;
        }).index;
}

} // namespace


void GreedySelector::iterate
(
    GreedyModel& model,
    const std::vector<Eigen::Index>& seed,
    const CandidateRows& rows,
    GreedyResult& result
) const
{
    const Eigen::Index minPoints = std::max<Eigen::Index>(options_.minPoints, seed.size());
    const Eigen::VectorXd d2 = squaredNorms(rows.values());
    const double scale = std::sqrt(rows.comm().max(d2.size() ? d2.maxCoeff() : 0.0));
    result.maxDisplacement = scale;
    std::vector<char> selected(rows.size(), 0);
    std::vector<Eigen::Index> next = seed;
    for (bool seeding = true; ; seeding = false)
    {
        const std::vector<Eigen::Index> added =
            addToModel(model, next, seeding, result);
        if (added.empty())
        {
            break;
        }
        for (const Eigen::Index i : added)
        {
            const Eigen::Index l = rows.local(i);
            if (l >= 0) selected[l] = 1;
            result.selected.push_back(i);
        }
        const Eigen::Index n = result.selected.size();
        const Values& e = model.residual();
        const Eigen::VectorXd err2 = squaredNorms(e);
        const CandidateRows::Best worst = globalArgmax(rows, err2, selected, all);
        const double eps =
            worst.index < 0 || scale == 0 ? 0.0 : std::sqrt(worst.value)/scale;
        result.historySize.push_back(n);
        result.historyError.push_back(eps);
        result.converged = eps <= options_.tolerance;
        if
        (
            (result.converged && n >= minPoints) || n >= options_.maxPoints
         || worst.index < 0 || result.dependent
        )
        {
            break;
        }
        next.assign(1, worst.index);
        if (options_.doubleEdged && n + 2 <= options_.maxPoints)
        {
            const Eigen::Index other = opposingWorst(rows, e, err2, selected, worst.index);
            if (other >= 0) next.push_back(other);
        }
    }
    model.coefficients(result.alpha, result.beta);
}

} // namespace dcprbf
