// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: Cholesky factor A = L L^T of a symmetric positive
// definite matrix whose rows/columns are appended and deleted one at a time.
//
// Append (A grows by the row (a^T, a_nn)):
//     l = L^{-1} a,   pivot = sqrt(a_nn - l.l),   L' = [L 0; l^T pivot]
// O(N^2) for the triangular solve, O(N) for the append itself.
//
// Delete row/column k: with L = [L11 0 0; l21^T l22 0; L31 l32 L33], the
// matrix without row/column k is  [L11 0; L31 L33'] [..]^T  where
//     L33' L33'^T = L33 L33^T + l32 l32^T
// a rank-one update computed with Givens rotations G_j that zero l32 against
// the columns of L33: [L33 l32] G_0 ... G_{n-1} = [L33' 0]. O((N-k)^2) flops
// plus moving the trailing block up/left by one, no refactorization.
//
// "Attached" rows: a matrix X = L^{-1} B (e.g. W = L^{-1} P) stays consistent
// through a deletion when the same rotations are applied to its rows:
//     X3' = top rows of G^T [X3; x_k^T]
// which remove() does for the matrix passed to it.
//
// Storage: column-major with spare capacity, so appends do not reallocate.
#pragma once

#include "Types.hpp"

#include <Eigen/Core>

namespace dcprbf
{

class UpdatableCholesky
{
public:
    UpdatableCholesky() : n_(0) {}

    Eigen::Index size() const { return n_; }

    //- The factor (only the lower triangle is meaningful)
    Eigen::Block<const Eigen::MatrixXd> matrixL() const
    {
        return L_.topLeftCorner(n_, n_);
    }

    //- Replace by the factor of a full matrix: lower triangle of L
    void assign(const Eigen::MatrixXd& L);

    void clear() { n_ = 0; }

    //- l = L^{-1} a (a has size() entries)
    Eigen::VectorXd forwardRow(const Eigen::VectorXd& a) const;

    //- Append the row (l^T, pivot), pivot > 0 (l = forwardRow(a),
    //  pivot = sqrt(a_nn - l.l), checked by the caller)
    void append(const Eigen::VectorXd& l, double pivot);

    //- Delete row/column k; rotate the rows of `attached` (at least size()
    //  rows, X = L^{-1} B) so that it stays L^{-1} B without row k; its row k
    //  is deleted and the rows below move up by one
    void remove(Eigen::Index k, Eigen::MatrixXd& attached);

    //- B <- L^{-1} B (B has size() rows)
    template<class Derived>
    void solveLowerInPlace(Eigen::MatrixBase<Derived>& B) const
    {
        L_.topLeftCorner(n_, n_).triangularView<Eigen::Lower>().solveInPlace(B);
    }

    //- B <- L^{-T} B
    template<class Derived>
    void solveUpperInPlace(Eigen::MatrixBase<Derived>& B) const
    {
        L_.topLeftCorner(n_, n_).triangularView<Eigen::Lower>().transpose()
            .solveInPlace(B);
    }

    //- B <- B L^{-T} (B has size() columns)
    template<class Derived>
    void solveRightUpperInPlace(Eigen::MatrixBase<Derived>& B) const
    {
        L_.topLeftCorner(n_, n_).triangularView<Eigen::Lower>().transpose()
            .template solveInPlace<Eigen::OnTheRight>(B);
    }

private:
    //- Make room for at least n rows/columns (amortized doubling)
    void reserve(Eigen::Index n);

    Eigen::MatrixXd L_;
    Eigen::Index n_;
};

} // namespace dcprbf
