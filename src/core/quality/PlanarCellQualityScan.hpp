// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the quality (TetQuality) of the cells of a 2D mesh
// (one cell thick, extruded) from one polygon per cell.
//
// A prism cell extruded from a polygon, moved in the plane (both caps by the
// same in-plane displacement, the extrusion coordinate fixed): every
// tetrahedron of CellQualityScan's decomposition (cell centre, face centre,
// edge) has A = diag(F, 1), with F the 2 x 2 map of one of the polygon's
// triangles (vertex average, edge) from the reference to the current
// polygon. So the cell's quality is the minimum over the polygon's n
// triangles of the tetrahedron quality with J = det F and |A|^2 = |F|^2 + 1:
// the value of CellQualityScan on the prism (equal to round-off), from n
// 2 x 2 maps instead of 6n tetrahedra (a quadrilateral: 4 instead of 24);
// a triangle cell: one map, its own (each triangle of the decomposition is
// an affine image of it; the same F to round-off). Triangles and
// quadrilaterals: one cell per SIMD lane from its points to its quality
// (detail::PlanarPolygonBatch); the other polygons' maps in SIMD lanes
// (detail::PlanarMapBatch), their final qualities too (detail::WorstBatch): the same
// operations and values.
// A degenerate reference triangle (quality 1 by TetQuality's convention) is
// judged in the plane: for references within ~1e-14 of degenerate, or thinner
// in the plane than ~1e-7 of the extrusion, the conventions can differ.
//
// Every cell's value depends only on its own points: a measurement with any
// number of OpenMP threads gives bit-identical values.
#pragma once

#include "PlanarMapBatch.hpp"
#include "PlanarPolygonBatch.hpp"
#include "TetMeasures.hpp"
#include "TetQuality.hpp"

#include <cstddef>
#include <memory>
#include <vector>

namespace dcprbf
{

class PlanarCellQualityScan
{
public:
    //- Polygons as compressed rows: cell i's polygon has the points
    //  polygonPoints[polygonStart[i] .. polygonStart[i+1]) in order around
    //  it (either direction); points0: the reference points, x y z per
    //  point; axis0, axis1: the in-plane components (0, 1 or 2)
    PlanarCellQualityScan
    (
        std::vector<std::size_t> polygonStart,
        std::vector<int> polygonPoints,
        const double* points0,
        int axis0,
        int axis1,
        TetQuality::Metric metric = TetQuality::Metric::sizeShape
    );

    //- Some of from's cells (indices into its cells, in this order), for
    //  the reference points points0 from's were made with: the same values
    //  as a scan built from their polygons (none classified again). Not
    //  concurrently with another subset of from (they share its scratch)
    PlanarCellQualityScan
    (
        const PlanarCellQualityScan& from,
        const std::vector<int>& cells,
        const double* points0
    );

    //- Number of cells
    std::size_t size() const { return polygonStart_.size() - 1; }

    //- Scans of fewer cells run on one thread (~20 ns a cell)
    static constexpr std::size_t minParallelCells = 8192;

    //- Quality of every cell for the points p (x y z per point, indexed
    //  as the reference points) into q (wide false: the SIMD kernels'
    //  default-target build even with AVX2 or AVX-512; the same values;
    //  not to be called concurrently on one scan: a scratch copy of the
    //  points is kept)
    void measure(const double* p, double* q, bool wide = true) const;

private:
    std::vector<std::size_t> polygonStart_;

    //- Indices into pointIds_ (the points renumbered in order of use)
    std::vector<int> polygonPoints_;
    std::vector<int> pointIds_;
    int axis0_, axis1_;

    //- The current in-plane points in that order (measure's scratch, kept)
    mutable std::unique_ptr<double[]> compact_;
    TetQuality::Metric metric_;

    //- The triangles and quadrilaterals (nearly every cell of a 2D mesh),
    //  one per SIMD lane
    detail::PlanarPolygonBatch<3> triangles_;
    detail::PlanarPolygonBatch<4> quads_;

    //- The other cells (polygons of n >= 5 points)
    std::vector<std::size_t> otherCells_;

    //- Per map (n per polygon: the triangles of the centre and the edge
    //  from point j), cell otherCells_[k]'s maps from mapStart_[k]: the
    //  inverse of its reference edge matrix (2 x 2, row major), and whether
    //  that is degenerate
    std::vector<std::size_t> mapStart_;
    std::vector<double> inverse0_;
    std::vector<char> degenerate_;

    //- The reference maps made (polygonPoints_ into pointIds_)
    void setUp(const double* points0);

    //- A subset's numbering of these points (pointIds_), -1 between
    //  subsets (only the entries a subset set are reset)
    mutable std::vector<int> subsetPoint_;

    //- Cell otherCells_[k]'s maps for the compact current in-plane points
    //  x into batch from position t
    void addMaps(std::size_t k, const double* x, detail::PlanarMapBatch& batch, std::size_t t) const;
};

} // namespace dcprbf
