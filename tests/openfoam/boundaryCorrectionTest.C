/*---------------------------------------------------------------------------*\
  dcpRBF tests: the boundary error's blend against its definition
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "dcpRBFBoundaryCorrection.H"
#include "dcpRBFPlaneProjection.H"
#include "RadialKernel.hpp"

#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>
#include <cstring>
#include <random>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

//- The blend by its definition: each corrected point within R of its
//  nearest target (brute force) gets that target's error times
//  phi(distance / R) (or its own radius's, if smaller), once
vectorField blendByDefinition
(
    const dcprbf::Points& x,
    const dcprbf::Points& targets,
    const boolList& corrected,
    const scalar maxRadius,
    const scalarField& targetRadius,
    const dcprbf::Values& error,
    const dcpRBFPlaneProjection& projection,
    label& nReached
)
{
    scalar eMax = 0;
    for (Eigen::Index b = 0; b < error.rows(); ++b)
    {
        eMax = max(eMax, error.row(b).norm());
    }
    const scalar R = min(dcpRBFBoundaryCorrection::radiusFactor*eMax, maxRadius);
    vectorField d(label(x.rows()), Zero);
    nReached = 0;
    for (Eigen::Index i = 0; i < x.rows(); ++i)
    {
        if (!corrected[label(i)])
        {
            continue;
        }
        Eigen::Index b = 0;
        (targets.rowwise() - x.row(i)).rowwise().squaredNorm().minCoeff(&b);
        const scalar r = std::sqrt((targets.row(b) - x.row(i)).squaredNorm());
        if (!(r < R))
        {
            continue;
        }
        ++nReached;
        const scalar Rb = targetRadius.empty() ? R : min(R, targetRadius[label(b)]);
        const scalar w = r < Rb ? dcprbf::kernels::WendlandC2{1.0/Rb}(r) : 0;
        d[label(i)] += w*projection.fromCore(error.row(b).data());
    }
    return d;
}


//- Random points in the unit box (in 2D in the mesh's plane), the targets
//  near y = 0; errors of growing size: radii that reach a few of the points
//  to most of them, and beyond the largest radius. The blend equals its
//  definition bit for bit in each case, on 1 and 2 threads
void compareBlends(const label dim, const bool perTargetRadius)
{
    testCase c(dim, 2, "movingPatches (bottom); staticPatches (top); supportRadius 1;");
    const dcpRBFPlaneProjection projection(c.mesh());
    std::mt19937 gen(11);
    std::uniform_real_distribution<scalar> u(0, 1);
    // more points than the blend runs on one thread for (8192)
    const label n = 12000, nTargets = 150;
    dcprbf::Points x(n, 3), targets(nTargets, 3);
    for (label i = 0; i < n; ++i)
    {
        x.row(i) << u(gen), u(gen), dim == 3 ? u(gen) : 0.0;
    }
    for (label b = 0; b < nTargets; ++b)
    {
        targets.row(b) << u(gen), 0.02*u(gen), dim == 3 ? u(gen) : 0.0;
    }
    boolList corrected(n);
    forAll(corrected, i)
    {
        corrected[i] = (i % 7 != 0);
    }
    const scalar maxRadius = 0.6;
    scalarField targetRadius;
    if (perTargetRadius)
    {
        targetRadius.setSize(nTargets);
        forAll(targetRadius, b)
        {
            targetRadius[b] = 0.05 + 0.5*u(gen);
        }
    }
    const dcpRBFBoundaryCorrection blend(x, targets, corrected, maxRadius, targetRadius);

    dcprbf::Values direction(nTargets, 3);
    for (label b = 0; b < nTargets; ++b)
    {
        direction.row(b) << u(gen) - 0.5, u(gen) - 0.5, dim == 3 ? u(gen) - 0.5 : 0.0;
    }
    label nCorrected = 0;
    forAll(corrected, i)
    {
        nCorrected += corrected[i];
    }
    bool few = false, many = false, capped = false;
    for (const scalar eMax : {0.001, 0.004, 0.02, 0.05, 0.2})
    {
        const dcprbf::Values error
        (
            eMax/direction.rowwise().norm().maxCoeff()*direction
        );
        label nReached = 0;
        const vectorField expected
        (
            blendByDefinition
            (
                x, targets, corrected, maxRadius, targetRadius, error, projection,
                nReached
            )
        );
        few = few || (nReached > 0 && 8*nReached < nCorrected);
        many = many || 2*nReached >= nCorrected;
        capped = capped || dcpRBFBoundaryCorrection::radiusFactor*eMax > maxRadius;
        for (const int threads : {1, 2})
        {
            const int nThreads = omp_get_max_threads();
            omp_set_num_threads(threads);
            vectorField d(n, Zero);
            const scalar R = blend.apply(error, projection, d);
            omp_set_num_threads(nThreads);
            EXPECT_DOUBLE_EQ
            (
                R, min(dcpRBFBoundaryCorrection::radiusFactor*eMax, maxRadius)
            );
            label nDiffer = 0;
            forAll(d, i)
            {
                nDiffer += std::memcmp(&d[i], &expected[i], sizeof(vector)) != 0;
            }
            EXPECT_EQ(nDiffer, 0)
                << "eMax " << eMax << ", " << nReached << " points reached, "
                << threads << " threads";
        }
    }
    // small, large and capped radii were exercised
    EXPECT_TRUE(few);
    EXPECT_TRUE(many);
    EXPECT_TRUE(capped);
}


TEST(BoundaryCorrection, BlendEqualsItsDefinition2D) { compareBlends(2, false); }
TEST(BoundaryCorrection, BlendEqualsItsDefinition3D) { compareBlends(3, false); }
TEST(BoundaryCorrection, BlendWithTargetRadiiEqualsItsDefinition) { compareBlends(3, true); }

} // namespace

// ************************************************************************* //
