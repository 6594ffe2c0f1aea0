// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the quality (TetQuality) of many polyhedral cells,
// in one tight loop.
//
// A cell is a list of faces, a face a list of point indices. Each cell is
// split into tetrahedra (cell centre, face centre, each edge of each face);
// the face centre is the average of the face's points, the cell centre the
// average of its face centres; the cell's quality is the minimum over its
// tetrahedra. A tetrahedral cell is measured once, as itself: each of its
// decomposition's tetrahedra is an affine image of it (its centres are fixed
// combinations of its vertices), so each has its A (equal to round-off;
// only whether a reference is degenerate, quality 1 by TetQuality's
// convention, is judged on the cell itself: for references within ~1e-14 of
// degenerate the two conventions can differ).
// The reference centres are computed once at construction (from the
// reference points), the topology is stored flat (compressed rows, the
// cells in Morton order of their first point (MortonOrder), each cell's
// faces with the cell, the points renumbered in the order the cells use
// them), and a measurement gathers the current points once into that order
// and reads the topology in order: no per-cell allocation,
// no per-step work on the reference mesh.
//
// Every cell's value depends only on its own points: a measurement with any
// number of OpenMP threads gives bit-identical values.
#pragma once

#include "TetQuality.hpp"

#include <cstddef>
#include <vector>

namespace dcprbf
{

class CellQualityScan
{
public:
    //- Cells as compressed rows: cell i has the faces
    //  cellFaces[cellStart[i] .. cellStart[i+1]), face f the points
    //  facePoints[faceStart[f] .. faceStart[f+1]); points0: the reference
    //  points, x y z per point (indexed by the point indices; those used
    //  are copied)
    CellQualityScan
    (
        std::vector<std::size_t> cellStart,
        std::vector<int> cellFaces,
        std::vector<std::size_t> faceStart,
        std::vector<int> facePoints,
        const double* points0,
        TetQuality::Metric metric = TetQuality::Metric::sizeShape
    );

    //- Number of cells
    std::size_t size() const { return cellStart_.size() - 1; }

    //- Quality of every cell for the points p (x y z per point, indexed
    //  as the reference points) into q
    void measure(const double* p, double* q) const;

private:
    std::vector<std::size_t> cellStart_;
    std::vector<int> cellFaces_;
    std::vector<std::size_t> faceStart_;
    std::vector<int> facePoints_;

    //- The caller's index of each cell, in the order stored (Morton order)
    std::vector<int> order_;

    //- The points used (their indices in the caller's numbering) in the
    //  order of first use; facePoints_ refer to this order
    std::vector<int> pointIds_;

    //- Their reference coordinates (x y z)
    std::vector<double> points0_;
    TetQuality::Metric metric_;

    //- Reference face centres per entry of cellFaces_ (x y z), reference
    //  cell centres (x y z)
    std::vector<double> faceCentres0_;
    std::vector<double> cellCentres0_;

    //- Is the cell whose faces start at entry k0 (four of them) a
    //  tetrahedron (four triangles)? Its vertices into v
    bool tetVertices(std::size_t k0, int v[4]) const;

    //- Quality of cell i for the compact current points x (buf,
    //  pointBuf: scratch space)
    double cellQuality
    (
        std::size_t i,
        const double* x,
        std::vector<double>& buf,
        std::vector<double>& pointBuf
    ) const;
};

} // namespace dcprbf
