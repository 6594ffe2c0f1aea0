// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "PointSetChecks.hpp"
#include "PointTree.hpp"

#include <sstream>

namespace dcprbf
{

Eigen::Index PointSetChecks::minimumSize(const LinearPolynomial& polynomial)
{
    return polynomial.enabled() ? polynomial.dim() + 1 : 1;
}


double PointSetChecks::extent(const Points& x)
{
    if (x.rows() == 0) return 0;
    return (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm();
}


void PointSetChecks::checkCoordinates(const Points& x, int dim, const char* what)
{
    if (!x.allFinite())
    {
        throw Error(std::string(what) + " coordinates are not finite");
    }
    if (dim == 2 && x.rows() > 0 && x.col(2).cwiseAbs().maxCoeff() > 0)
    {
        throw Error("2D interpolation needs points projected onto z = 0");
    }
}


void PointSetChecks::checkDistinct(const Points& x, const char* what)
{
    const double ext = extent(x);
    Eigen::Index i = 0, j = 1;
    if
    (
        (ext == 0 && x.rows() > 1)
     || (ext > 0 && PointTree::findCoincident(x, 1e-10*ext, i, j))
    )
    {
        std::ostringstream os;
        os  << "duplicate " << what << "s " << i << " and " << j << " at ("
            << x.row(i) << ")";
        throw Error(os.str());
    }
}


void PointSetChecks::checkControlSet
(
    const Points& x,
    const LinearPolynomial& polynomial
)
{
    const Eigen::Index need = minimumSize(polynomial);
    if (x.rows() < need)
    {
        std::ostringstream os;
        os  << x.rows() << " control points are too few: at least " << need
            << " are needed"
            << (polynomial.enabled() ? " to carry the polynomial" : "");
        throw Error(os.str());
    }
    checkCoordinates(x, polynomial.dim(), "control point");
    checkDistinct(x, "control point");
    polynomial.checkUnisolvent(x);
}

} // namespace dcprbf
