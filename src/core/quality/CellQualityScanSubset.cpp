// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// CellQualityScan, continued: a scan of some of another scan's cells.
#include "CellQualityScan.hpp"
#include "ScratchNumbering.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace dcprbf
{

CellQualityScan::CellQualityScan
(
    const CellQualityScan& from,
    const std::vector<int>& cells
)
:
    cellStart_(1, 0),
    faceStart_(1, 0),
    metric_(from.metric_)
{
    const std::size_t n = from.order_.size();
    if (from.position_.size() != n)
    {
        from.position_.assign(n, -1);
        for (std::size_t i = 0; i < n; ++i) from.position_[std::size_t(from.order_[i])] = int(i);
    }
    // the cells in from's stored (Morton) order
    std::vector<std::pair<int, int>> byPosition;
    byPosition.reserve(cells.size());
    for (std::size_t k = 0; k < cells.size(); ++k)
    {
        if (cells[k] < 0 || std::size_t(cells[k]) >= n)
        {
            throw std::invalid_argument("CellQualityScan: a subset's cell index");
        }
        byPosition.emplace_back(from.position_[std::size_t(cells[k])], int(k));
    }
    std::sort(byPosition.begin(), byPosition.end());
    for (std::size_t k = 1; k < byPosition.size(); ++k)
    {
        if (byPosition[k].first == byPosition[k - 1].first)
        {
            throw std::invalid_argument("CellQualityScan: a subset's cell given twice");
        }
    }

    // from's points renumbered in the order the cells use them (from's
    // scratch numbering, reset below where set)
    ScratchNumbering local(from.subsetPoint_, from.pointIds_.size());
    const auto point = [&](const int p)
    {
        return local(p, [&](const int q)
        {
            pointIds_.push_back(from.pointIds_[std::size_t(q)]);
            const double* x0 = &from.points0_[3*std::size_t(q)];
            points0_.insert(points0_.end(), x0, x0 + 3);
        });
    };
    order_.reserve(cells.size());
    kind_.reserve(cells.size());
    slot_.reserve(cells.size());
    for (const std::pair<int, int>& pk : byPosition)
    {
        const std::size_t i = std::size_t(pk.first);
        order_.push_back(pk.second);
        kind_.push_back(from.kind_[i]);
        const std::size_t from0 = std::size_t(from.slot_[i]);
        if (from.kind_[i] != general)
        {
            slot_.push_back(int(vertices_.size()));
            const int nv = nVertices(from.kind_[i]);
            for (int v = 0; v < nv; ++v) vertices_.push_back(point(from.vertices_[from0 + v]));
            continue;
        }
        slot_.push_back(int(cellStart_.size()) - 1);
        for (std::size_t k = from.cellStart_[from0]; k < from.cellStart_[from0 + 1]; ++k)
        {
            for (std::size_t j = from.faceStart_[k]; j < from.faceStart_[k + 1]; ++j)
            {
                facePoints_.push_back(point(from.facePoints_[j]));
            }
            faceStart_.push_back(facePoints_.size());
            const double* fc0 = &from.faceCentres0_[3*k];
            faceCentres0_.insert(faceCentres0_.end(), fc0, fc0 + 3);
        }
        cellStart_.push_back(faceStart_.size() - 1);
        const double* cc0 = &from.cellCentres0_[3*from0];
        cellCentres0_.insert(cellCentres0_.end(), cc0, cc0 + 3);
    }
}

} // namespace dcprbf
