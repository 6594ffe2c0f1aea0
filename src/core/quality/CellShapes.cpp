// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "CellShapes.hpp"

namespace dcprbf
{

bool tetrahedronVertices
(
    const std::size_t* start,
    const std::size_t nFaces,
    const int* points,
    int v[4]
)
{
    if (nFaces != 4) return false;
    for (std::size_t k = 0; k < 4; ++k)
    {
        if (start[k + 1] - start[k] != 3) return false;
    }
    const int* a = points + start[0];
    const int* b = points + start[1];
    v[0] = a[0]; v[1] = a[1]; v[2] = a[2];
    v[3] = -1;
    for (int j = 0; j < 3; ++j)
    {
        if (b[j] != a[0] && b[j] != a[1] && b[j] != a[2]) v[3] = b[j];
    }
    if (v[3] < 0 || v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) return false;

    // each face three of the four vertices, each leaving out another one
    bool left[4] = {false, false, false, false};
    for (std::size_t k = 0; k < 4; ++k)
    {
        const int* f = points + start[k];
        int out = -1;
        for (int i = 0; i < 4; ++i)
        {
            if (f[0] != v[i] && f[1] != v[i] && f[2] != v[i])
            {
                if (out >= 0) return false;
                out = i;
            }
        }
        if (out < 0 || left[out] || f[0] == f[1] || f[1] == f[2] || f[2] == f[0]) return false;
        left[out] = true;
    }
    return true;
}


namespace
{

//- Are a and b neighbours in the cycle c of n points?
bool joined(const int* c, const std::size_t n, const int a, const int b)
{
    for (std::size_t j = 0; j < n; ++j)
    {
        const int p = c[j], q = c[(j + 1) % n];
        if ((p == a && q == b) || (p == b && q == a)) return true;
    }
    return false;
}

} // namespace


bool prismVertices
(
    const std::size_t* start,
    const std::size_t nFaces,
    const int* points,
    int v[6]
)
{
    if (nFaces != 5) return false;
    const int* tri[2] = {nullptr, nullptr};
    const int* quad[3] = {nullptr, nullptr, nullptr};
    int nTri = 0, nQuad = 0;
    for (std::size_t k = 0; k < 5; ++k)
    {
        const std::size_t n = start[k + 1] - start[k];
        if (n == 3 && nTri < 2) tri[nTri++] = points + start[k];
        else if (n == 4 && nQuad < 3) quad[nQuad++] = points + start[k];
        else return false;
    }

    // each point of the first triangle joined by a quadrilateral's edge to
    // exactly one point of the second, distinct
    for (int i = 0; i < 3; ++i)
    {
        v[i] = tri[0][i];
        v[3 + i] = -1;
        for (int j = 0; j < 3; ++j)
        {
            if (tri[0][i] == tri[1][j]) return false;
            for (int q = 0; q < 3; ++q)
            {
                if (joined(quad[q], 4, tri[0][i], tri[1][j]))
                {
                    if (v[3 + i] >= 0 && v[3 + i] != tri[1][j]) return false;
                    v[3 + i] = tri[1][j];
                }
            }
        }
        if (v[3 + i] < 0) return false;
    }
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]
     || v[3] == v[4] || v[4] == v[5] || v[5] == v[3])
    {
        return false;
    }

    // quadrilateral i is the cycle (v_i, v_i+1, v_i+4, v_i+3) for one edge
    // (i, i+1) of the first triangle each
    bool used[3] = {false, false, false};
    for (int q = 0; q < 3; ++q)
    {
        bool found = false;
        for (int i = 0; i < 3 && !found; ++i)
        {
            const int j = (i + 1) % 3;
            found =
                !used[i]
             && joined(quad[q], 4, v[i], v[j])
             && joined(quad[q], 4, v[j], v[3 + j])
             && joined(quad[q], 4, v[3 + j], v[3 + i])
             && joined(quad[q], 4, v[3 + i], v[i]);
            if (found) used[i] = true;
        }
        if (!found) return false;
    }
    return true;
}


namespace
{

//- The hexahedron's face opposite its first (the one sharing no point
//  with it), null if none or more than one
const int* oppositeFace(const std::size_t* start, const int* points)
{
    const int* first = points + start[0];
    const int* opposite = nullptr;
    for (std::size_t k = 1; k < 6; ++k)
    {
        const int* f = points + start[k];
        bool shares = false;
        for (int a = 0; a < 4; ++a)
        {
            for (int b = 0; b < 4; ++b) shares = shares || f[a] == first[b];
        }
        if (!shares)
        {
            if (opposite) return nullptr;
            opposite = f;
        }
    }
    return opposite;
}


//- v[4..8): each point v[0..4) of the first face joined by a side face's
//  edge to exactly one point of the opposite face, distinct; false if not
bool joinOpposite
(
    const std::size_t* start,
    const int* points,
    const int* opposite,
    int v[8]
)
{
    for (int i = 0; i < 4; ++i)
    {
        v[4 + i] = -1;
        for (int j = 0; j < 4; ++j)
        {
            for (std::size_t k = 1; k < 6; ++k)
            {
                const int* f = points + start[k];
                if (f == opposite || !joined(f, 4, v[i], opposite[j])) continue;
                if (v[4 + i] >= 0 && v[4 + i] != opposite[j]) return false;
                v[4 + i] = opposite[j];
            }
        }
        if (v[4 + i] < 0) return false;
        for (int j = 4; j < 4 + i; ++j)
        {
            if (v[j] == v[4 + i]) return false;
        }
    }
    return true;
}


//- Is the opposite face the cycle v4 v5 v6 v7 and side face i the cycle
//  (v_i, v_i+1, v_i+5, v_i+4) for one edge (i, i+1) of the first each?
bool sidesAreCycles
(
    const std::size_t* start,
    const int* points,
    const int* opposite,
    const int v[8]
)
{
    for (int i = 0; i < 4; ++i)
    {
        if (!joined(opposite, 4, v[4 + i], v[4 + (i + 1) % 4])) return false;
    }
    bool used[4] = {false, false, false, false};
    for (std::size_t k = 1; k < 6; ++k)
    {
        const int* f = points + start[k];
        if (f == opposite) continue;
        bool found = false;
        for (int i = 0; i < 4 && !found; ++i)
        {
            const int j = (i + 1) % 4;
            found =
                !used[i]
             && joined(f, 4, v[i], v[j])
             && joined(f, 4, v[j], v[4 + j])
             && joined(f, 4, v[4 + j], v[4 + i])
             && joined(f, 4, v[4 + i], v[i]);
            if (found) used[i] = true;
        }
        if (!found) return false;
    }
    return true;
}

} // namespace


bool hexahedronVertices
(
    const std::size_t* start,
    const std::size_t nFaces,
    const int* points,
    int v[8]
)
{
    if (nFaces != 6) return false;
    for (std::size_t k = 0; k < 6; ++k)
    {
        if (start[k + 1] - start[k] != 4) return false;
    }
    const int* first = points + start[0];
    for (int i = 0; i < 4; ++i)
    {
        v[i] = first[i];
        for (int j = 0; j < i; ++j)
        {
            if (v[i] == v[j]) return false;
        }
    }

    const int* opposite = oppositeFace(start, points);
    return
        opposite
     && joinOpposite(start, points, opposite, v)
     && sidesAreCycles(start, points, opposite, v);
}

} // namespace dcprbf
