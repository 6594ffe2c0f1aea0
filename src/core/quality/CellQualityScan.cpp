// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "CellQualityScan.hpp"
#include "CellShapes.hpp"
#include "MortonOrder.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace dcprbf
{

namespace
{

//- Row r of the compressed rows (from, fromStart) appended to (to, toStart)
template<class T>
void appendRow
(
    std::vector<T>& to,
    std::vector<std::size_t>& toStart,
    const std::vector<T>& from,
    const std::vector<std::size_t>& fromStart,
    const std::size_t r
)
{
    to.insert
    (
        to.end(),
        from.begin() + std::ptrdiff_t(fromStart[r]),
        from.begin() + std::ptrdiff_t(fromStart[r + 1])
    );
    toStart.push_back(to.size());
}


//- Throw unless the compressed rows are consistent (each ending at its
//  array's size), every cell has faces and every face index is a face of
//  at least 3 points (fewer than 2^31 cell faces)
void checkRows
(
    const std::vector<std::size_t>& cellStart,
    const std::vector<int>& cellFaces,
    const std::vector<std::size_t>& faceStart,
    const std::vector<int>& facePoints
)
{
    if (cellStart.empty() || cellStart.back() != cellFaces.size()
     || faceStart.empty() || faceStart.back() != facePoints.size())
    {
        throw std::invalid_argument("CellQualityScan: inconsistent compressed rows");
    }
    for (std::size_t i = 0; i + 1 < cellStart.size(); ++i)
    {
        if (cellStart[i + 1] <= cellStart[i])
        {
            throw std::invalid_argument("CellQualityScan: a cell without faces");
        }
    }
    if (cellFaces.size() > std::size_t(std::numeric_limits<int>::max()))
    {
        throw std::invalid_argument("CellQualityScan: more than 2^31 cell faces");
    }
    const std::size_t nFaces = faceStart.size() - 1;
    for (const int f : cellFaces)
    {
        if (f < 0 || std::size_t(f) >= nFaces || faceStart[f + 1] - faceStart[f] < 3)
        {
            throw std::invalid_argument("CellQualityScan: face index or face size");
        }
    }
}

} // namespace


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
    faceStart_(std::move(faceStart)),
    facePoints_(std::move(facePoints)),
    metric_(metric)
{
    checkRows(cellStart, cellFaces, faceStart_, facePoints_);
    orderCells(cellStart, cellFaces, points0);
    renumberPoints(cellFaces);
    storeFacesWithCells(cellFaces);
    std::vector<int>().swap(cellFaces);
    classify(cellStart);
    setUpReference(points0);
}


void CellQualityScan::orderCells
(
    std::vector<std::size_t>& cellStart,
    std::vector<int>& cellFaces,
    const double* points0
)
{
    // The cells visited in Morton order of one point each, so that the
    // points below are numbered with locality whatever the cells' numbering
    const std::size_t nCells = cellStart.size() - 1;
    std::vector<double> key(3*nCells);
    for (std::size_t i = 0; i < nCells; ++i)
    {
        const int f = cellFaces[cellStart[i]];
        const int pi = facePoints_[faceStart_[f]];
        if (pi < 0) throw std::invalid_argument("CellQualityScan: point index");
        for (int d = 0; d < 3; ++d) key[3*i + d] = points0[3*std::size_t(pi) + d];
    }
    order_ = mortonOrder(key.data(), nCells);
    std::vector<std::size_t> start(1, 0);
    std::vector<int> faces;
    faces.reserve(cellFaces.size());
    for (const int c : order_)
    {
        appendRow(faces, start, cellFaces, cellStart, std::size_t(c));
    }
    cellStart.swap(start);
    cellFaces.swap(faces);
}


void CellQualityScan::renumberPoints(const std::vector<int>& cellFaces)
{
    // The points renumbered in the order in which the cells use them (a
    // measurement reads them from a compact copy, mostly in order)
    int maxIndex = -1;
    for (const int pi : facePoints_)
    {
        if (pi < 0) throw std::invalid_argument("CellQualityScan: point index");
        maxIndex = std::max(maxIndex, pi);
    }
    std::vector<int> local(std::size_t(maxIndex + 1), -1);
    for (const int f : cellFaces)
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
}


void CellQualityScan::storeFacesWithCells(const std::vector<int>& cellFaces)
{
    // Each cell's faces stored with the cell (a face shared by two cells
    // twice): a measurement reads the topology in order
    std::vector<std::size_t> entryStart(1, 0);
    std::vector<int> entryPoints;
    entryStart.reserve(cellFaces.size() + 1);
    for (const int f : cellFaces)
    {
        appendRow(entryPoints, entryStart, facePoints_, faceStart_, std::size_t(f));
    }
    faceStart_.swap(entryStart);
    facePoints_.swap(entryPoints);
}


void CellQualityScan::setUpReference(const double* points0)
{
    // The points used, and the general cells' face and cell centres
    points0_.resize(3*pointIds_.size());
    for (std::size_t i = 0; i < pointIds_.size(); ++i)
    {
        for (int d = 0; d < 3; ++d) points0_[3*i + d] = points0[3*std::size_t(pointIds_[i]) + d];
    }
    const std::size_t nGeneral = cellStart_.size() - 1;
    faceCentres0_.resize(3*(faceStart_.size() - 1));
    cellCentres0_.resize(3*nGeneral);
    for (std::size_t g = 0; g < nGeneral; ++g)
    {
        double* cc = &cellCentres0_[3*g];
        cc[0] = cc[1] = cc[2] = 0;
        for (std::size_t k = cellStart_[g]; k < cellStart_[g + 1]; ++k)
        {
            double* fc = &faceCentres0_[3*k];
            fc[0] = fc[1] = fc[2] = 0;
            for (std::size_t j = faceStart_[k]; j < faceStart_[k + 1]; ++j)
            {
                for (int d = 0; d < 3; ++d) fc[d] += points0_[3*std::size_t(facePoints_[j]) + d];
            }
            const double n = double(faceStart_[k + 1] - faceStart_[k]);
            for (int d = 0; d < 3; ++d)
            {
                fc[d] /= n;
                cc[d] += fc[d];
            }
        }
        const double n = double(cellStart_[g + 1] - cellStart_[g]);
        for (int d = 0; d < 3; ++d) cc[d] /= n;
    }
}


void CellQualityScan::classify(std::vector<std::size_t>& cellStart)
{
    const std::size_t nCells = cellStart.size() - 1;
    if (6*nCells > std::size_t(std::numeric_limits<int>::max()))
    {
        throw std::invalid_argument("CellQualityScan: more than 2^31/6 cells");
    }
    kind_.resize(nCells);
    slot_.resize(nCells);
    std::vector<std::size_t> generalStart(1, 0), entryStart(1, 0);
    std::vector<int> entryPoints;
    for (std::size_t i = 0; i < nCells; ++i)
    {
        const std::size_t k0 = cellStart[i], nFaces = cellStart[i + 1] - k0;
        int v[8];
        if (tetrahedronVertices(&faceStart_[k0], nFaces, facePoints_.data(), v))
        {
            kind_[i] = tetrahedron;
            slot_[i] = int(vertices_.size());
            vertices_.insert(vertices_.end(), v, v + 4);
        }
        else if (prismVertices(&faceStart_[k0], nFaces, facePoints_.data(), v))
        {
            kind_[i] = prism;
            slot_[i] = int(vertices_.size());
            vertices_.insert(vertices_.end(), v, v + 6);
        }
        else if (hexahedronVertices(&faceStart_[k0], nFaces, facePoints_.data(), v))
        {
            kind_[i] = hexahedron;
            slot_[i] = int(vertices_.size());
            vertices_.insert(vertices_.end(), v, v + 8);
        }
        else
        {
            kind_[i] = general;
            slot_[i] = int(generalStart.size()) - 1;
            for (std::size_t k = k0; k < k0 + nFaces; ++k)
            {
                appendRow(entryPoints, entryStart, facePoints_, faceStart_, k);
            }
            generalStart.push_back(entryStart.size() - 1);
        }
    }
    cellStart_.swap(generalStart);
    faceStart_.swap(entryStart);
    facePoints_.swap(entryPoints);
    vertices_.shrink_to_fit();
}


std::vector<int> CellQualityScan::cellsOfKind(const Kind k) const
{
    std::vector<int> cells;
    for (std::size_t i = 0; i < kind_.size(); ++i)
    {
        if (kind_[i] == k) cells.push_back(order_[i]);
    }
    std::sort(cells.begin(), cells.end());
    return cells;
}


CellQualityScan::Shapes CellQualityScan::shapes() const
{
    Shapes s;
    for (const Kind k : kind_)
    {
        ++(k == tetrahedron ? s.tetrahedra : k == prism ? s.prisms
         : k == hexahedron ? s.hexahedra : s.others);
    }
    return s;
}

} // namespace dcprbf
