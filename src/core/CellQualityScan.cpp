// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "CellQualityScan.hpp"
#include "MortonOrder.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace dcprbf
{

CellQualityScan::CellQualityScan
(
    std::vector<std::size_t> cellStart,
    std::vector<int> cellFaces,
    std::vector<std::size_t> faceStart,
    std::vector<int> facePoints,
    const double* points0,
    TetQuality::Metric metric
)
:
    cellStart_(std::move(cellStart)),
    cellFaces_(std::move(cellFaces)),
    faceStart_(std::move(faceStart)),
    facePoints_(std::move(facePoints)),
    metric_(metric),
    faceCentres0_(3*cellFaces_.size()),
    cellCentres0_(3*(cellStart_.empty() ? 0 : cellStart_.size() - 1))
{
    if (cellStart_.empty() || cellStart_.back() != cellFaces_.size()
     || faceStart_.empty() || faceStart_.back() != facePoints_.size())
    {
        throw std::invalid_argument("CellQualityScan: inconsistent compressed rows");
    }
    for (std::size_t i = 0; i + 1 < cellStart_.size(); ++i)
    {
        if (cellStart_[i + 1] <= cellStart_[i])
        {
            throw std::invalid_argument("CellQualityScan: a cell without faces");
        }
    }
    if (cellFaces_.size() > std::size_t(std::numeric_limits<int>::max()))
    {
        throw std::invalid_argument("CellQualityScan: more than 2^31 cell faces");
    }
    const std::size_t nFaces = faceStart_.size() - 1;
    for (const int f : cellFaces_)
    {
        if (f < 0 || std::size_t(f) >= nFaces || faceStart_[f + 1] - faceStart_[f] < 3)
        {
            throw std::invalid_argument("CellQualityScan: face index or face size");
        }
    }

    // The cells visited in Morton order of one point each, so that the
    // points below are numbered with locality whatever the cells' numbering
    {
        const std::size_t nCells = cellStart_.size() - 1;
        std::vector<double> key(3*nCells);
        for (std::size_t i = 0; i < nCells; ++i)
        {
            const int f = cellFaces_[cellStart_[i]];
            const int pi = facePoints_[faceStart_[f]];
            if (pi < 0) throw std::invalid_argument("CellQualityScan: point index");
            for (int d = 0; d < 3; ++d) key[3*i + d] = points0[3*std::size_t(pi) + d];
        }
        order_ = mortonOrder(key.data(), nCells);
        std::vector<std::size_t> start(1, 0);
        std::vector<int> faces;
        faces.reserve(cellFaces_.size());
        for (const int c : order_)
        {
            faces.insert
            (
                faces.end(),
                cellFaces_.begin() + std::ptrdiff_t(cellStart_[c]),
                cellFaces_.begin() + std::ptrdiff_t(cellStart_[c + 1])
            );
            start.push_back(faces.size());
        }
        cellStart_.swap(start);
        cellFaces_.swap(faces);
    }

    // The points renumbered in the order in which the cells use them (a
    // measurement reads them from a compact copy, mostly in order)
    int maxIndex = -1;
    for (const int pi : facePoints_)
    {
        if (pi < 0) throw std::invalid_argument("CellQualityScan: point index");
        maxIndex = std::max(maxIndex, pi);
    }
    std::vector<int> local(std::size_t(maxIndex + 1), -1);
    for (const int f : cellFaces_)
    {
        for (std::size_t j = faceStart_[f]; j < faceStart_[f + 1]; ++j)
        {
            if (local[facePoints_[j]] < 0)
            {
                local[facePoints_[j]] = int(pointIds_.size());
                pointIds_.push_back(facePoints_[j]);
            }
        }
    }
    for (int& pi : facePoints_) pi = local[pi];

    // Each cell's faces stored with the cell (a face shared by two cells
    // twice): a measurement reads the topology in order
    {
        std::vector<std::size_t> entryStart(1, 0);
        std::vector<int> entryPoints;
        entryStart.reserve(cellFaces_.size() + 1);
        for (int& f : cellFaces_)
        {
            entryPoints.insert
            (
                entryPoints.end(),
                facePoints_.begin() + std::ptrdiff_t(faceStart_[f]),
                facePoints_.begin() + std::ptrdiff_t(faceStart_[f + 1])
            );
            f = int(entryStart.size()) - 1;
            entryStart.push_back(entryPoints.size());
        }
        faceStart_.swap(entryStart);
        facePoints_.swap(entryPoints);
    }
    points0_.resize(3*pointIds_.size());
    for (std::size_t i = 0; i < pointIds_.size(); ++i)
    {
        for (int d = 0; d < 3; ++d) points0_[3*i + d] = points0[3*std::size_t(pointIds_[i]) + d];
    }
    for (std::size_t i = 0; i + 1 < cellStart_.size(); ++i)
    {
        double* cc = &cellCentres0_[3*i];
        cc[0] = cc[1] = cc[2] = 0;
        for (std::size_t k = cellStart_[i]; k < cellStart_[i + 1]; ++k)
        {
            const int f = cellFaces_[k];
            double* fc = &faceCentres0_[3*k];
            fc[0] = fc[1] = fc[2] = 0;
            for (std::size_t j = faceStart_[f]; j < faceStart_[f + 1]; ++j)
            {
                for (int d = 0; d < 3; ++d) fc[d] += points0_[3*std::size_t(facePoints_[j]) + d];
            }
            const double n = double(faceStart_[f + 1] - faceStart_[f]);
            for (int d = 0; d < 3; ++d)
            {
                fc[d] /= n;
                cc[d] += fc[d];
            }
        }
        const double n = double(cellStart_[i + 1] - cellStart_[i]);
        for (int d = 0; d < 3; ++d) cc[d] /= n;
    }
}

} // namespace dcprbf
