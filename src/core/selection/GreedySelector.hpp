// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: greedy selection of control points among candidate
// boundary points (Rendall & Allen 2009), optionally double-edged
// (Wang et al. 2015).
//
// Given candidates x_i with displacements d_i (i < Nb):
//   1. seed C with a small set that carries the polynomial (see seed());
//   2. interpolate d on C, residual e_i = d_i - s_C(x_i) at every candidate;
//   3. relative error  eps = max_{i not in C} |e_i| / max_i |d_i|;
//      stop when (eps <= tolerance and |C| >= minPoints), |C| == maxPoints or
//      every candidate is in C;
//   4. add the candidate w with the largest |e_w| (ties: the lowest index);
//      double-edged: also the largest |e_j| among those with e_j . e_w < 0
//      (the "other edge" of the error), both from the same residual; go to 2.
//
// run() drives this loop on any GreedyModel. select(), the production entry
// point, runs it incrementally (IncrementalGreedyModel: one new row of the
// Cholesky factor and one Newton basis column, O(N Nb) per point, nothing
// re-solved). The tests and benchmarks run the same loop on a reference model
// that re-solves the whole system per iteration (tests/core/reference), so the
// two differ only in round-off.
//
// The polynomial frame is the bounding box of the candidates
// (LinearPolynomial::boundingBox), beta is written in it.
#pragma once

#include "CandidateRows.hpp"
#include "GreedyModel.hpp"
#include "LinearPolynomial.hpp"
#include "RadialKernel.hpp"
#include "SaddleFactorization.hpp"

#include <functional>
#include <memory>
#include <vector>

namespace dcprbf
{

struct GreedyOptions
{
    //- Stop at relative max error <= tolerance (> 0)
    double tolerance = 1e-3;

    //- At least this many points (0: the seed's size)
    Eigen::Index minPoints = 0;

    //- At most this many points (>= minPoints and >= the seed's size)
    Eigen::Index maxPoints = 1000;

    //- Add the worst point of the opposite error direction too
    bool doubleEdged = false;

    //- Seed candidate indices; empty: automatic (see GreedySelector::seed)
    std::vector<Eigen::Index> seed;
};


struct GreedyResult
{
    explicit GreedyResult(const LinearPolynomial& f) : frame(f) {}

    //- Selected candidate indices in selection order (the seed first)
    std::vector<Eigen::Index> selected;

    //- Their coordinates, in the same order
    Points centres;

    //- Kernel weights (row j for selected[j]) and polynomial coefficients
    //  (in frame) of the interpolant on the selected points
    Values alpha;
    Eigen::MatrixX3d beta;
    LinearPolynomial frame;

    //- History: number of control points and relative max error after the
    //  seed and after every iteration
    std::vector<Eigen::Index> historySize;
    std::vector<double> historyError;

    //- Was the tolerance met?
    bool converged = false;

    //- Did the selection stop at a point numerically dependent on the
    //  selected ones (the kernel matrix singular to round-off with it: the
    //  interpolant cannot fit better with this kernel and radius)?
    bool dependent = false;

    //- max_i |d_i| (the error scale)
    double maxDisplacement = 0;

    //- select(): the factorization of the selected set, ready for
    //  IncrementalSaddleSolver(std::move(*factorization)); null from models
    //  that keep none (GreedyModel::releaseFactorization)
    std::unique_ptr<SaddleFactorization> factorization;
};


class GreedySelector
{
public:
    //- Makes the model run() drives, for the (checked) candidates and
    //  displacements, in the polynomial frame of the result
    using ModelFactory = std::function
    <
        std::unique_ptr<GreedyModel>
        (
            const RadialKernel& kernel,
            const LinearPolynomial& frame,
            const Points& candidates,
            const Values& displacements
        )
    >;

    //- Throws Error for inconsistent options (tolerance <= 0, maxPoints <
    //  minPoints, ...) or kernel settings (TPS without polynomial, dim)
    GreedySelector
    (
        const RadialKernel& kernel,
        bool polynomial,
        int dim,
        const GreedyOptions& options = GreedyOptions()
    );

    //- Incremental selection. Throws Error for ill-posed input (sizes,
    //  non-finite values, duplicate candidates, candidates that cannot carry
    //  the polynomial, a candidate numerically dependent on the selected ones)
    GreedyResult select(const Points& candidates, const Values& displacements) const;

    //- The same selection on candidates divided over ranks (collective):
    //  each rank holds its block of the rows (the Nb/P x N basis); indices
    //  (selected, options' seed) are global, the result is the same on every
    //  rank and the same as select() on all the rows in one block, whatever
    //  the division. An Error is thrown on every rank alike.
    GreedyResult select(const CandidateRows& candidates) const;

    //- The selection on the model made by makeModel (select() is run() on an
    //  IncrementalGreedyModel): the same input checks, seed and loop
    GreedyResult run
    (
        const ModelFactory& makeModel,
        const Points& candidates,
        const Values& displacements
    ) const;

    //- The automatic seed. Without the polynomial: the candidate of largest
    //  |d|. With it, dim + 1 points spanning a well-shaped simplex: the one of
    //  largest |d|, the candidate farthest from it, the one farthest from the
    //  line through both, and in 3D the one farthest from their plane. Error
    //  if the candidates are collinear (2D) or coplanar (3D).
    std::vector<Eigen::Index> seed
    (
        const Points& candidates,
        const Values& displacements
    ) const;

    //- The automatic seed of candidates divided over ranks (global indices)
    std::vector<Eigen::Index> seed(const CandidateRows& candidates) const;

    const GreedyOptions& options() const { return options_; }

private:
    void checkInput(const CandidateRows& candidates) const;

    //- The loop
    void iterate
    (
        GreedyModel& model,
        const std::vector<Eigen::Index>& seed,
        const CandidateRows& candidates,
        GreedyResult& result
    ) const;

    RadialKernel kernel_;
    bool polynomial_;
    int dim_;
    GreedyOptions options_;
};

} // namespace dcprbf
