// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core, module kernels: the radial functions (RadialKernel:
// Wendland C0/C2/C4/C6, thin-plate spline, Gaussian, inverse multiquadric;
// support radius), the linear polynomial that augments them
// (LinearPolynomial) and the blocks of the augmented interpolation matrix
// (AugmentedKernel).
#pragma once

#include "RadialKernel.hpp"
#include "LinearPolynomial.hpp"
#include "AugmentedKernel.hpp"
