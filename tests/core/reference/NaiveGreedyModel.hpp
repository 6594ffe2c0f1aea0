// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF test reference (not in libdcpRBF): the reference model of the greedy
// selection, and selectNaive(), GreedySelector's loop run on it. Every
// change of the selected set C assembles and solves the whole saddle system
// again (SaddleSolver: Cholesky + Schur complement, LU for TPS; O(N^3)) and
// evaluates the interpolant at every candidate (RbfEvaluator; O(N Nb)).
// Used by the tests (the incremental model must pick the same points) and the
// benchmark; not meant for production.
#pragma once

#include "GreedyModel.hpp"
#include "GreedySelector.hpp"
#include "LinearPolynomial.hpp"
#include "RadialKernel.hpp"

namespace dcprbf
{

class NaiveGreedyModel : public GreedyModel
{
public:
    //- The model keeps references to candidates and displacements
    NaiveGreedyModel
    (
        const RadialKernel& kernel,
        const LinearPolynomial& polynomial,
        const Points& candidates,
        const Values& displacements
    );

    void add(const std::vector<Eigen::Index>& indices) override;
    const Values& residual() const override { return residual_; }
    void coefficients(Values& alpha, Eigen::MatrixX3d& beta) const override;

private:
    RadialKernel kernel_;
    LinearPolynomial polynomial_;
    const Points& x_;
    const Values& d_;
    std::vector<Eigen::Index> selected_;
    Values alpha_;
    Eigen::MatrixX3d beta_;
    Values residual_;
};


//- The selection of selector.select() re-solving the full system per
//  iteration: selector.run() on a NaiveGreedyModel (no factorization)
GreedyResult selectNaive
(
    const GreedySelector& selector,
    const Points& candidates,
    const Values& displacements
);

} // namespace dcprbf
