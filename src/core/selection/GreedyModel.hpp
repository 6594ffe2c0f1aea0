// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: what the greedy control-point selection needs from
// an interpolation model of the candidate points.
//
// A model holds the candidates x_i and their displacements d_i and, for the
// selected subset C (in selection order), the interpolant s_C of d on C. It
// reports the residual e_i = d_i - s_C(x_i) at every candidate. The
// production model is IncrementalGreedyModel (O(N Nb) per added point); the
// tests and benchmarks have a reference one (tests/core/reference:
// NaiveGreedyModel, a fresh saddle-point solve and evaluation per change).
#pragma once

#include "Types.hpp"

#include <memory>
#include <vector>

namespace dcprbf
{

class SaddleFactorization;

class GreedyModel
{
public:
    virtual ~GreedyModel() = default;

    //- Append these candidates (in order) to the selected set, then bring
    //  (a single candidate numerically dependent on the selected set: an
    //  Error, nothing appended)
    //  residual() up to date. The first call must carry the polynomial.
    virtual void add(const std::vector<Eigen::Index>& indices) = 0;

    //- e_i = d_i - s_C(x_i) at every candidate (Nb x 3)
    virtual const Values& residual() const = 0;

    //- Kernel weights (row j for the j-th selected point) and polynomial
    //  coefficients of s_C
    virtual void coefficients(Values& alpha, Eigen::MatrixX3d& beta) const = 0;

    //- Hand over the factorization of the selected set, if the model keeps
    //  one (null otherwise); the model is unusable afterwards
    virtual std::unique_ptr<SaddleFactorization> releaseFactorization()
    {
        return nullptr;
    }
};

} // namespace dcprbf
