/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFTrialWindow.H"

#include <algorithm>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::dcpRBFTrialWindow::lowest
(
    const scalarField& q,
    const label n
)
{
    // the n lowest here, then the global n-th lowest of all of them
    std::vector<scalar> sorted(q.begin(), q.end());
    const label nLocal = max(label(0), min(n, label(sorted.size())));
    std::partial_sort(sorted.begin(), sorted.begin() + nLocal, sorted.end());

    List<scalarList> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = scalarList(sorted.begin(), sorted.begin() + nLocal);
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    std::vector<scalar> merged;
    for (const scalarList& l : all)
    {
        merged.insert(merged.end(), l.begin(), l.end());
    }
    if (merged.empty() || n <= 0)
    {
        return labelList();
    }
    const std::size_t k = std::min(std::size_t(n), merged.size()) - 1;
    std::nth_element(merged.begin(), merged.begin() + k, merged.end());
    const scalar threshold = merged[k];

    DynamicList<label> positions(nLocal);
    forAll(q, i)
    {
        if (q[i] <= threshold)
        {
            positions.append(i);
        }
    }
    return labelList(std::move(positions));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFTrialWindow::dcpRBFTrialWindow
(
    const polyMesh& mesh,
    const labelUList& regionCells,
    const List<FixedList<scalar, 3>>& regionCentres,
    const scalarField& q,
    const label n,
    const pointField& points0,
    const dcprbf::TetQuality::Metric metric
)
:
    indices_(lowest(q, n)),
    cells_(labelUIndList(regionCells, indices_)),
    centres_(UIndirectList<FixedList<scalar, 3>>(regionCentres, indices_)),
    quality_(mesh, cells_, points0, metric)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFTrialWindow::size() const
{
    return returnReduce(cells_.size(), sumOp<label>());
}


Foam::dcpRBFQualityRegion::rankedCell
Foam::dcpRBFTrialWindow::worst(const pointField& p) const
{
    // none here: above every quality
    const scalarField q(quality_.compute(p));
    dcpRBFQualityRegion::rankedCell local({VGREAT, 0, 0, 0});
    forAll(q, i)
    {
        const dcpRBFQualityRegion::rankedCell c
        ({q[i], centres_[i][0], centres_[i][1], centres_[i][2]});
        local = std::min(local, c);
    }

    List<dcpRBFQualityRegion::rankedCell> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = local;
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    dcpRBFQualityRegion::rankedCell w(local);
    for (const auto& c : all)
    {
        w = std::min(w, c);
    }
    if (w[0] == VGREAT)
    {
        w[0] = 1;
    }
    return w;
}

// ************************************************************************* //
