/*---------------------------------------------------------------------------*\
  dcpRBF tests: the bump runs shared by the OpenFOAM-tier tests
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "bumpRun.H"
#include "dcpRBFCellQuality.H"
#include "cellByCellQuality.H"

#include <gtest/gtest.h>
#include <fstream>
#include <sstream>

namespace Foam
{
namespace dcpRBFTest
{

const std::string patches =
    "movingPatches (bottom); staticPatches (top left right); supportRadius 0.8;";

std::vector<std::vector<double>> stepRows(const testCase& c)
{
    std::vector<std::vector<double>> rows;
    std::ifstream is(c.dir()/"postProcessing"/"dcpRBF"/"0"/"dcpRBF.dat");
    std::string line;
    while (std::getline(is, line))
    {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ls(line);
        std::vector<double> row;
        std::string word;
        // (std::stod: nan too, the mean of qualityScan lowest)
        while (ls >> word) row.push_back(std::stod(word));
        rows.push_back(row);
    }
    return rows;
}

bumpRun runBump(const std::string& controlPoints, label nSteps, label n,
    scalar perStep, const std::vector<scalar>& amplitudes,
    const std::string& extraCoeffs, scalar (*shape)(scalar))
{
    // a boundary layer: cells 30 times thinner at the bottom wall than at
    // the top, where a reduced set's boundary error folds them first
    testCase c(2, n, patches + " boundaryCorrection false; guardIterations 0; " + extraCoeffs +
        " controlPoints { " + controlPoints + " }", "wall",
        "{ type fixedValue; value uniform (0 0 0); }", "(1 30 1)");
    autoPtr<motionSolver> ms(select(c));
    auto& solver = refCast<dcpRBFMotionSolver>(ms());
    bumpRun b;
    const pointField p0(c.mesh().points());
    const labelList cells(identity(c.mesh().nCells()));
    for (label step = 1; step <= nSteps; ++step)
    {
        ++c.runTime();
        const scalar a = amplitudes.empty() ? perStep*step : amplitudes[step - 1];
        prescribe(solver.pointDisplacement(), "bottom", [a, shape](const point& x)
        {
            return vector(0, a*(shape ? shape(x.x()) : std::sin(2*constant::mathematical::pi*x.x())), 0);
        });
        const pointField p(ms->newPoints());
        // the new points (the measured ones, reused when the displacement
        // is the one they were made from) are those of the displacement
        // the step leaves, bitwise, after trials, rescues and blends too
        const pointField fresh(ms->curPoints());
        scalar d = 0;
        forAll(p, i) d = max(d, mag(p[i] - fresh[i]));
        EXPECT_EQ(d, 0) << "step " << step << ": newPoints() != curPoints()";
        // the logged minimum is the written mesh's (its worst cells are at
        // the moving wall, in reach), after trials made before or after the
        // measurement, rescues and blends alike
        b.minQuality.push_back(gMin(cellByCellQuality(c.mesh(), cells, p0, p)));
        c.mesh().movePoints(p);
        b.points.push_back(p);
    }
    // no constraint repeated off its axis here: every step's new points
    // are the measured ones (not made a second time)
    EXPECT_EQ(solver.nReusedPoints(), nSteps);
    b.nMeasurements = solver.nMeasurements();
    b.rows = stepRows(c);
    EXPECT_EQ(label(b.rows.size()), nSteps);
    for (std::size_t s = 0; s < b.rows.size() && s < b.minQuality.size(); ++s)
    {
        EXPECT_NEAR(b.rows[s][cMinQ], b.minQuality[s], 1e-12) << "step " << s + 1;
    }
    return b;
}

//- Minimum quality per step of the bump run
std::vector<double> minQualityPerStep(const std::string& controlPoints, label nSteps,
    std::vector<std::vector<double>>* rowsOut, label n, scalar perStep)
{
    const bumpRun b(runBump(controlPoints, nSteps, n, perStep));
    if (rowsOut) *rowsOut = b.rows;
    std::vector<double> q;
    for (const auto& row : b.rows) q.push_back(row[cMinQ]);
    return q;
}

//- Largest change of point velocity between steps, max |x(n+1) - 2x(n) + x(n-1)|
scalar largestJerk(const bumpRun& b)
{
    scalar j = 0;
    for (std::size_t s = 1; s + 1 < b.points.size(); ++s)
    {
        forAll(b.points[s], i)
        {
            j = max(j, mag(b.points[s + 1][i] - 2*b.points[s][i] + b.points[s - 1][i]));
        }
    }
    return j;
}

} // End namespace dcpRBFTest
} // End namespace Foam

// ************************************************************************* //
