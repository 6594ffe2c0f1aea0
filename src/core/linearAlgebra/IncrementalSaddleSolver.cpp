// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "IncrementalSaddleSolver.hpp"
#include "PointSetChecks.hpp"

#include <cmath>
#include <sstream>

namespace dcprbf
{

IncrementalSaddleSolver::IncrementalSaddleSolver
(
    const RadialKernel& kernel,
    const LinearPolynomial& polynomial
)
:
    f_(kernel, polynomial)
{}


IncrementalSaddleSolver::IncrementalSaddleSolver(SaddleFactorization factorization)
:
    f_(std::move(factorization))
{}


Eigen::Index IncrementalSaddleSolver::minimumSize() const
{
    return PointSetChecks::minimumSize(polynomial());
}


void IncrementalSaddleSolver::reset(const Points& centres)
{
    f_.clear();
    PointSetChecks::checkControlSet(centres, polynomial());
    f_.factorize(centres);
}


Eigen::Index IncrementalSaddleSolver::coincident(const Eigen::RowVector3d& x) const
{
    const Points c = centres();
    const Eigen::RowVector3d lo = c.colwise().minCoeff().cwiseMin(x);
    const Eigen::RowVector3d hi = c.colwise().maxCoeff().cwiseMax(x);
    const double tolSq = std::pow(1e-10*(hi - lo).norm(), 2);
    for (Eigen::Index j = 0; j < c.rows(); ++j)
    {
        if ((c.row(j) - x).squaredNorm() <= tolSq) return j;
    }
    return -1;
}


void IncrementalSaddleSolver::add(const Eigen::RowVector3d& point)
{
    if (size() < minimumSize())
    {
        throw Error
        (
            "IncrementalSaddleSolver::add: the control set must first be"
            " factorized with at least minimumSize() points (reset)"
        );
    }
    PointSetChecks::checkCoordinates(point, polynomial().dim(), "control point");
    const Eigen::Index j = coincident(point);
    if (j >= 0)
    {
        std::ostringstream os;
        os  << "cannot add (" << point << "): it duplicates control point " << j;
        throw Error(os.str());
    }

    Eigen::VectorXd l;
    const double pivotSq = f_.newRow(point.data(), l);
    if (f_.acceptablePivot(point.data(), pivotSq))
    {
        f_.append(point.data(), l, std::sqrt(pivotSq));
        return;
    }
    std::ostringstream os;
    os  << "cannot add (" << point << "): numerically dependent on the"
        << " control points (kernel matrix singular to round-off)";
    if (kernel().positiveDefinite()) throw Error(os.str());

    // TPS: Phi_c may just need a larger shift. Refactorize; on failure the
    // saved factorization comes back.
    const SaddleFactorization saved = f_;
    Points c(size() + 1, 3);
    c << centres(), point;
    try
    {
        f_.raiseShiftAndFactorize(c);
    }
    catch (const Error&)
    {
        f_ = saved;
        throw Error(os.str());
    }
}


void IncrementalSaddleSolver::remove(Eigen::Index i)
{
    const Eigen::Index n = size();
    if (i < 0 || i >= n)
    {
        std::ostringstream os;
        os  << "cannot remove control point " << i << ": there are " << n;
        throw Error(os.str());
    }
    if (n - 1 < minimumSize())
    {
        std::ostringstream os;
        os  << "cannot remove control point " << i << ": " << n - 1
            << " points would be left, at least " << minimumSize()
            << " are needed";
        throw Error(os.str());
    }
    if (polynomial().enabled())
    {
        const Points c = centres();
        Points rest(n - 1, 3);
        rest << c.topRows(i), c.bottomRows(n - 1 - i);
        try
        {
            polynomial().checkUnisolvent(rest);
        }
        catch (const Error& e)
        {
            throw Error
            (
                "cannot remove control point " + std::to_string(i) + ": "
              + e.what()
            );
        }
    }
    f_.remove(i);
}


void IncrementalSaddleSolver::replace
(
    Eigen::Index i,
    const Eigen::RowVector3d& point
)
{
    if (i < 0 || i >= size())
    {
        throw Error("cannot replace control point " + std::to_string(i)
            + ": there are " + std::to_string(size()));
    }
    add(point);
    try
    {
        remove(i);
    }
    catch (const Error&)
    {
        f_.remove(size() - 1);  // undo the add: back to the valid old set
        throw;
    }
}


void IncrementalSaddleSolver::solve
(
    const Values& values,
    Values& alpha,
    Eigen::MatrixX3d& beta
) const
{
    if (values.rows() != size() || size() == 0)
    {
        throw Error
        (
            "IncrementalSaddleSolver::solve: " + std::to_string(values.rows())
          + " values for " + std::to_string(size()) + " control points"
        );
    }
    if (!values.allFinite())
    {
        throw Error("values at the control points are not finite");
    }
    f_.solve(values, alpha, beta);
}

} // namespace dcprbf
