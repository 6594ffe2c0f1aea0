/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Application
    dcpRBFQualityScanBenchmark

Description
    Times the per-step cell-quality measurement on a case's mesh (all cells,
    a smooth deformation of 1 % of the domain): the cell-by-cell
    dcpRBFCellQuality (the measurement of the region before the flat scan)
    against dcpRBFQualityRegion's flat scan (dcprbf::CellQualityScan), on
    1 and 2 OpenMP threads, in one run; checks that they agree and that the
    scan gives the same values on 1 and 2 threads. Prints one line per
    variant: median of -repeat measurements in ms.

    dcpRBFQualityScanBenchmark [-case dir] [-repeat 7] [-simdWidth 512|256|0]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "clockTime.H"
#include "dcpRBFCellQuality.H"
#include "cellByCellQuality.H"
#include "dcpRBFQualityRegion.H"
#include "SimdWidth.hpp"
#include "dcpRBFPlaneProjection.H"

#include <omp.h>
#include <algorithm>

using namespace Foam;

template<class F>
scalar medianMs(const label n, F f)
{
    std::vector<scalar> t;
    for (label i = 0; i < n; ++i)
    {
        clockTime c;
        f();
        t.push_back(1000*c.elapsedTime());
    }
    std::sort(t.begin(), t.end());
    return t[t.size()/2];
}

int main(int argc, char *argv[])
{
    argList::addOption("repeat", "n", "measurements per variant (7)");
    argList::addOption
    (
        "referenceRepeat", "n",
        "measurements of the cell-by-cell reference (default: repeat; 0: skip it)"
    );
    argList::addOption
    (
        "simdWidth", "bits",
        "cap on the quality kernels' vectors: 512 (AVX-512, default), 256 (AVX2), 0 (default build)"
    );
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"
    const label n = args.getOrDefault<label>("repeat", 7);
    const label nRef = args.getOrDefault<label>("referenceRepeat", n);
    dcprbf::SimdWidth::limit(unsigned(max(0, args.getOrDefault<label>("simdWidth", 512))));
    Info<< "SIMD width " << label(dcprbf::SimdWidth::bits()) << " bits" << nl;

    const pointField& p0 = mesh.points();
    const boundBox bb(p0);
    // 2D: the motion of a 2D case, in the plane and the same for the front
    // and back twins (the empty coordinate neither moves nor enters)
    const label empty = mesh.nSolutionD() == 2 ? findMin(mesh.solutionD()) : -1;
    pointField p(p0);
    forAll(p, i)
    {
        vector x((p0[i] - bb.min())/max(bb.mag(), SMALL));
        if (empty >= 0) x[empty] = 0;
        p[i] += 0.01*bb.mag()*vector(Foam::sin(3*x.y()), Foam::sin(2*x.z() + x.x()), 0.5*Foam::sin(4*x.x()));
        if (empty >= 0) p[i][empty] = p0[i][empty];
    }

    // the region of every cell: the "moving points" are all points (no
    // other sources of the check, not affine beyond: all cells checked)
    const dcpRBFPlaneProjection projection(mesh);
    clockTime c;
    const dcpRBFQualityRegion region
    (
        mesh, projection, p0, projection.toCore(p0), dcprbf::Points(0, 3),
        GREAT, false, dcprbf::TetQuality::Metric::sizeShape
    );
    Info<< "cells " << region.cells().size() << ", points " << mesh.nPoints()
        << ", region set-up " << 1000*c.elapsedTime() << " ms" << nl;
    mesh.cells();
    const bool reference = nRef > 0;

    const label nt = omp_get_max_threads();
    scalarField qOld, q1, q2;
    for (const label threads : {1, 2})
    {
        omp_set_num_threads(threads);
        const scalar tOld = reference
          ? medianMs(nRef, [&]{ qOld = cellByCellQuality(mesh, region.cells(), p0, p); })
          : 0;
        const scalar tNew = medianMs(n, [&]{ (threads == 1 ? q1 : q2) = region.quality(p); });
        // what the guard calls: the scan, count, min, mean and the ranking
        // of the 5 worst and best
        const scalar tSummary = medianMs(n, [&]{ region.measure(p, 5); });
        // as the guard calls it unless swapRule nearest swaps: no best cells
        const scalar tNoBest =
            medianMs(n, [&]{ region.measure(p, 5, scalarField(), -1, false); });
        // qualityScan lowest: the 5 worst exact, the others bounded
        const scalar tLowest =
            medianMs(n, [&]{ region.measure(p, 5, scalarField(), 5); });
        Info<< threads << " thread(s): ";
        if (reference)
        {
            Info<< "dcpRBFCellQuality " << tOld << " ms, ";
        }
        Info<< "flat scan " << tNew << " ms";
        if (reference)
        {
            Info<< ", ratio " << tOld/tNew;
        }
        Info<< ", measure() with the summary " << tSummary << " ms"
            << " (without the best cells " << tNoBest << " ms)"
            << ", with the 5 lowest only (qualityScan lowest) " << tLowest
            << " ms" << nl;
    }
    // the flat scan's time per cell by the path a cell takes (1 thread):
    // each kind's cells as a subset of the region's scan
    omp_set_num_threads(1);
    typedef dcprbf::CellQualityScan::Kind kind;
    const std::pair<kind, const char*> kinds[] =
    {
        {kind::hexahedron, "hexahedra"}, {kind::prism, "prisms"},
        {kind::tetrahedron, "tetrahedra"}, {kind::general, "polyhedra (from their faces)"}
    };
    Info<< "per cell, 1 thread:";
    for (const auto& k : kinds)
    {
        const labelList positions(region.cellQuality().cellsOfKind(k.first));
        if (positions.empty()) continue;
        const dcpRBFCellQuality sub(region.cellQuality(), positions, p0);
        scalarField qs;
        const scalar t = medianMs(n, [&]{ qs = sub.compute(p); });
        Info<< ' ' << k.second << ' ' << positions.size() << ": "
            << 1e6*t/positions.size() << " ns";
    }
    Info<< nl;

    omp_set_num_threads(nt);
    if (reference)
    {
        Info<< "max |flat - dcpRBFCellQuality| " << max(mag(q1 - qOld)) << ", ";
    }
    Info<< "1 vs 2 threads identical: " << Switch(q1 == q2)
        << ", min quality " << min(q1) << nl;
    return 0;
}
