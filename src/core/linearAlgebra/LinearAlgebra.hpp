// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core, module linearAlgebra: the saddle-point system of an
// RBF interpolant with a polynomial, factorised so that a centre is added or
// removed in O(N^2) (SaddleFactorization, over UpdatableCholesky), solved
// incrementally (IncrementalSaddleSolver) with Rippa's leave-one-out errors;
// the k smallest values of a list (SmallestValues).
#pragma once

#include "UpdatableCholesky.hpp"
#include "SaddleFactorization.hpp"
#include "IncrementalSaddleSolver.hpp"
#include "SmallestValues.hpp"
