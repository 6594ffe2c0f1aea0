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
// Tetrahedra (4 vertices), triangular prisms (6) and hexahedra (8;
// CellShapes) are stored by their vertices and measured in SIMD lanes
// (detail::TetBatch; detail::PrismBatch, detail::HexBatch: one cell per
// lane, its 18 or 24 tetrahedra and its worst in the lane), the other
// cells by their faces (each cell's faces stored with the cell, reference
// face and cell centres computed once; their tetrahedra gathered into a
// detail::TetBatch). The cells are visited in Morton order of their first point
// (MortonOrder) in blocks, the points renumbered in the order the cells use
// them; a measurement gathers the current points once into that order: no
// per-cell allocation, no per-step work on the reference mesh but the
// prisms' and hexahedra's reference edges (recomputed: storing them would
// take 18 or 24 x 9 doubles per cell).
//
// Every cell's value depends only on its own points and no operation is
// contracted: a measurement with any number of OpenMP threads, in any
// block and on either SIMD build gives bit-identical values.
#pragma once

#include "HexBatch.hpp"
#include "PrismBatch.hpp"
#include "TetBatch.hpp"
#include "WorstBatch.hpp"
#include "TetQuality.hpp"
#include "CellQualityBound.hpp"

#include <cstddef>
#include <memory>
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

    //- A scan of some of from's cells (indices in from's caller order, each
    //  once): cell k of the new scan is from's cell cells[k]. Copied from
    //  from's classified cells and reference data, not built from the
    //  topology again (a trial window's cells of a 10M-cell region: 0.4 s
    //  from the mesh). Their qualities are from's, bit for bit. Not
    //  concurrently with another subset of from (they share its scratch)
    CellQualityScan(const CellQualityScan& from, const std::vector<int>& cells);

    //- Number of cells
    std::size_t size() const { return order_.size(); }

    //- The points the cells use (indices as the reference points), each
    //  once, in the order of first use
    const std::vector<int>& pointIds() const { return pointIds_; }

    //- Scans of fewer cells run on one thread (~0.1-0.3 us a cell)
    static constexpr std::size_t minParallelCells = 2048;

    //- Quality of every cell for the points p (x y z per point, indexed
    //  as the reference points) into q (wide false: the SIMD kernels'
    //  default-target build even with AVX2 or AVX-512; the same values;
    //  not to be called concurrently on one scan: a scratch copy of the
    //  points and each thread's batches are kept)
    void measure(const double* p, double* q, bool wide = true) const;

    //- The qualities that rank the k lowest cells for the points p, into
    //  q: exact (as measure()) for every cell that may be among the k
    //  lowest and for every inverted one; for each of the others a lower
    //  bound of its quality (CellQualityBound) above the k-th lowest and
    //  above 0. So the k lowest of q, the minimum and the cells of
    //  quality <= 0 are those of measure(), bit for bit; a sum is not.
    //  Cells are measured in the order of their bounds: those below the
    //  k-th lowest bound, then those whose bound is not above the k-th
    //  lowest quality so found (plus 1e-9). Returns the number of cells
    //  measured. The bounds are set up on the first call
    std::size_t measureLowest
    (
        const double* p,
        double* q,
        std::size_t k,
        bool wide = true
    ) const;

    //- Each cell's lower bound (CellQualityBound) for the points p into lb
    //  (the caller's order; -infinity: none)
    void lowerBounds(const double* p, double* lb) const;

    //- How a cell is measured: from its vertices (a tetrahedron: one
    //  measure; a prism: detail::PrismBatch; a hexahedron:
    //  detail::HexBatch) or from its faces (general)
    enum Kind : unsigned char { general, tetrahedron, prism, hexahedron };

    //- Number of vertices of a kind measured from its vertices
    static int nVertices(const Kind k)
    {
        return k == tetrahedron ? 4 : k == prism ? 6 : 8;
    }

    //- The cells (the caller's indices) measured as kind k
    std::vector<int> cellsOfKind(Kind k) const;

    //- How many cells are measured by each path
    struct Shapes
    {
        std::size_t tetrahedra = 0, prisms = 0, hexahedra = 0, others = 0;
    };
    Shapes shapes() const;

private:

    //- The caller's index of each cell, in the order stored (Morton order)
    std::vector<int> order_;

    //- Its inverse (the stored position of each caller index), made on
    //  the first subset constructed from this scan
    mutable std::vector<int> position_;
    //- A subset's numbering of these points, -1 between subsets (only the
    //  entries a subset set are reset: no pass over every point per subset)
    mutable std::vector<int> subsetPoint_;

    //- Per cell: its kind, and its first vertex in vertices_ (tetrahedra,
    //  prisms, hexahedra) or its row in the general cells' topology
    std::vector<Kind> kind_;
    std::vector<int> slot_;

    //- The tetrahedra's, prisms' and hexahedra's vertices (CellShapes'
    //  order)
    std::vector<int> vertices_;

    //- The general cells: each one's faces stored with it (entries),
    //  general cell g has the entries cellStart_[g] .. cellStart_[g+1],
    //  entry k the points facePoints_[faceStart_[k] .. faceStart_[k+1])
    std::vector<std::size_t> cellStart_;
    std::vector<std::size_t> faceStart_;
    std::vector<int> facePoints_;

    //- The points used (their indices in the caller's numbering) in the
    //  order of first use; vertices_ and facePoints_ refer to this order
    std::vector<int> pointIds_;

    //- Their reference coordinates (x y z)
    std::vector<double> points0_;

    //- The current points in that order (measure's scratch, kept)
    mutable std::unique_ptr<double[]> compact_;
    TetQuality::Metric metric_;

    //- The general cells' reference face centres per entry (x y z) and
    //  reference cell centres (x y z)
    std::vector<double> faceCentres0_;
    std::vector<double> cellCentres0_;

    //- The cells (cellStart, cellFaces) reordered in Morton order of one
    //  reference point each (order_ set)
    void orderCells
    (
        std::vector<std::size_t>& cellStart,
        std::vector<int>& cellFaces,
        const double* points0
    );

    //- The points the cells use (faces cellFaces) numbered in the order of
    //  first use (pointIds_ set, facePoints_ renumbered)
    void renumberPoints(const std::vector<int>& cellFaces);

    //- faceStart_ and facePoints_ made entries: each cell's faces
    //  (cellFaces) stored with it, in order
    void storeFacesWithCells(const std::vector<int>& cellFaces);

    //- The reference data: points0_ from the reference points points0,
    //  the general cells' faceCentres0_ and cellCentres0_
    void setUpReference(const double* points0);

    //- Sort the cells (kind_, slot_, vertices_) and keep the general
    //  cells' entries only; cellFaces: entry numbers (the identity)
    void classify(std::vector<std::size_t>& cellStart);

    //- Each cell's bound (in the order stored) and vertices (compact
    //  numbering, compressed rows), set up by setUpBounds()
    mutable std::vector<CellQualityBound> bounds_;
    mutable std::vector<std::size_t> boundStart_;
    mutable std::vector<int> boundVertices_;

    //- measureLowest's scratch: the bounds, the cells to measure
    mutable std::vector<double> lower_;
    mutable std::vector<int> pick_;

    //- Every cell's position (0, 1, ...: measure()'s list)
    mutable std::vector<int> every_;

    //- Cells measured at once
    static constexpr std::size_t blockCells = 256;

    //- A thread's scratch space for measureBlock
    struct Scratch
    {
        detail::TetBatch tets;
        detail::PrismBatch prisms;
        detail::HexBatch hexes;
        detail::WorstBatch finals;
        std::vector<double> buf;
        std::size_t first[blockCells];

        Scratch(const TetQuality::Metric metric, const bool wide)
        :
            finals(metric, wide)
        {}
    };

    //- Each thread's scratch space, kept from one measurement to the next
    //  (allocating and clearing a block's batches each time costs ~0.1 ms)
    mutable std::vector<std::unique_ptr<Scratch>> scratch_;

    //- The qualities of the m cells (at most blockCells) at the stored
    //  positions at[0 .. m) for the compact current points x into q (the
    //  caller's order)
    void measureBlock
    (
        const int* at,
        std::size_t m,
        const double* x,
        Scratch& s,
        double* q
    ) const;

    //- measureBlock's layout: each of the m cells at the stored positions
    //  at[0 .. m) its place in its batch (s.first: a prism's or a
    //  hexahedron's, else its first tetrahedron's), the batches sized
    //  (inline: defined and used in CellQualityScanMeasure.cpp alone)
    inline void placeBlock(const int* at, std::size_t m, Scratch& s) const;

    //- measureBlock's input: those cells' prisms, hexahedra and tetrahedra
    //  for the compact current points x into their places in s's batches
    //  (inline: as placeBlock)
    inline void fillBlock(const int* at, std::size_t m, const double* x, Scratch& s) const;

    //- The current points p into the compact copy (in parallel if
    //  parallel); the copy
    const double* gather(const double* p, bool parallel) const;

    //- This thread's scratch space
    Scratch& scratch(bool wide) const;

    //- The qualities of the cells at the stored positions at (ascending)
    //  for the compact current points x into q
    void measureCells(const std::vector<int>& at, const double* x, double* q, bool wide) const;

    //- The bounds' set-up (bounds_, boundStart_, boundVertices_)
    void setUpBounds() const;

    //- measureLowest's end: the cells not measured get their bounds
    //  (lower_) in q; the number measured
    std::size_t boundTheRest(const std::vector<char>& measured, double* q) const;

    //- Stored cell i's kappa: the largest |E^-1|_2 of its tetrahedra
    //  (CellQualityBound::inverseNorm)
    double kappa(std::size_t i) const;

    //- Number of tetrahedra of general cell g
    std::size_t tetCount(std::size_t g) const;

    //- General cell g's tetrahedra for the compact current points x into
    //  batch from position t (buf: scratch space)
    void addTets
    (
        std::size_t g,
        const double* x,
        detail::TetBatch& batch,
        std::size_t t,
        std::vector<double>& buf
    ) const;
};

} // namespace dcprbf
