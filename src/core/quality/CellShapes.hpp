// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: tetrahedra, triangular prisms and hexahedra recognised from
// their faces (CellQualityScan measures them from their vertices).
//
// A cell is given as its faces: face k (0 .. nFaces-1) has the points
// points[start[k] .. start[k+1]). The vertices come out in the order the
// SIMD kernels expect:
// - a tetrahedron (four triangles; the first face and the one point of the
//   second face not on it): v0 .. v3;
// - a prism (two triangles and three quadrilaterals, each quadrilateral
//   joining an edge of the first triangle to the points of the second
//   triangle joined to its ends by an edge): the first triangle v0 v1 v2
//   and the point joined to each, v3 v4 v5;
// - a hexahedron (six quadrilaterals: the first face, the opposite one
//   sharing no point with it, and four joining an edge of the first to the
//   points of the opposite one joined to its ends by an edge): the first
//   face v0 v1 v2 v3 and the point joined to each, v4 v5 v6 v7.
// Anything else (a twisted or malformed cell, repeated points) is not
// recognised: the caller measures it from its faces.
#pragma once

#include <cstddef>

namespace dcprbf
{

//- The cell is a tetrahedron: its vertices into v
bool tetrahedronVertices
(
    const std::size_t* start,
    std::size_t nFaces,
    const int* points,
    int v[4]
);

//- The cell is a triangular prism: its vertices into v
bool prismVertices
(
    const std::size_t* start,
    std::size_t nFaces,
    const int* points,
    int v[6]
);

//- The cell is a hexahedron: its vertices into v
bool hexahedronVertices
(
    const std::size_t* start,
    std::size_t nFaces,
    const int* points,
    int v[8]
);

} // namespace dcprbf
