// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the RBF system of a control set that changes by
// single points (dynamic control points), updated in O(N^2) per change.
//
// The numerics are in SaddleFactorization (Cholesky of Phi_c = Phi + c P P^T,
// W = L^{-1} P, Schur complement S = W^T W; append = one new row of L,
// delete = Givens downdate). This class owns the control set's rules:
//  - add(x):     refused (Error, nothing changed) for a non-finite point,
//                z != 0 in 2D, a point within 1e-10 x extent of a centre, or
//                a pivot^2 <= 1e-14 K_c(x, x) (numerically dependent point).
//                TPS only: a failed pivot may mean the shift c is too small;
//                then c is raised tenfold and the set refactorized, O(N^3),
//                counted in factorizations().
//  - remove(i):  refused when fewer than minimumSize() points would be left
//                or the rest cannot carry the polynomial (collinear in 2D,
//                coplanar in 3D).
//  - replace(i, x): the swap of dynamic control points, add then remove.
//
// The polynomial frame is fixed at construction (e.g. the bounding box of all
// boundary points) so that beta keeps its meaning through the changes.
//
// Typical use (values in the order of centres()):
//     IncrementalSaddleSolver s(kernel,
//         LinearPolynomial::boundingBox(true, 3, boundaryPoints));
//     s.reset(initialControlPoints);      // O(N^3) once
//     s.replace(i, newPoint);             // O(N^2)
//     s.solve(values, alpha, beta);       // O(N^2)
//     RbfEvaluator e(s.kernel(), s.polynomial());
//     e.assign(s.centres(), alpha, beta);
#pragma once

#include "SaddleFactorization.hpp"

namespace dcprbf
{

class IncrementalSaddleSolver
{
public:
    //- Empty control set
    IncrementalSaddleSolver
    (
        const RadialKernel& kernel,
        const LinearPolynomial& polynomial
    );

    //- Take over a factorization (e.g. the one a GreedySelector built)
    explicit IncrementalSaddleSolver(SaddleFactorization factorization);

    //- Check and factorize this set from scratch, O(N^3). Throws Error if
    //  ill-posed (then the solver is empty).
    void reset(const Points& centres);

    //- Append a centre (it becomes index size() - 1); reset() first
    void add(const Eigen::RowVector3d& point);

    //- Delete centre i; the centres after it move down by one
    void remove(Eigen::Index i);

    //- Add the new point, then remove centre i (the new point ends last).
    //  Either both happen or neither.
    void replace(Eigen::Index i, const Eigen::RowVector3d& point);

    //- Kernel weights (N x 3, in centre order) and polynomial coefficients
    //  (m x 3, in polynomial()'s frame) for values at the centres; O(N^2)
    void solve(const Values& values, Values& alpha, Eigen::MatrixX3d& beta) const;

    Eigen::Index size() const { return f_.size(); }

    //- dim + 1 with the polynomial, 1 without
    Eigen::Index minimumSize() const;

    //- The current centres, in order
    Points centres() const { return f_.centres(); }

    const RadialKernel& kernel() const { return f_.kernel().kernel(); }
    const LinearPolynomial& polynomial() const { return f_.polynomial(); }

    //- Number of O(N^3) factorizations so far
    int factorizations() const { return f_.factorizations(); }

    //- The factorization (leave-one-out errors: inverseDiagonal())
    const SaddleFactorization& factorization() const { return f_; }

private:
    //- Index of a centre within round-off distance of x, or -1
    Eigen::Index coincident(const Eigen::RowVector3d& x) const;

    SaddleFactorization f_;
};

} // namespace dcprbf
