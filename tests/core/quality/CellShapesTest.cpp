// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the recognition of tetrahedra, prisms and hexahedra from their
// faces.
#include "CellShapes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace dcprbf;

namespace
{

// A cell as compressed face rows
struct Faces
{
    std::vector<std::size_t> start{0};
    std::vector<int> points;

    explicit Faces(const std::vector<std::vector<int>>& faces)
    {
        for (const auto& f : faces)
        {
            points.insert(points.end(), f.begin(), f.end());
            start.push_back(points.size());
        }
    }

    std::size_t size() const { return start.size() - 1; }
};

bool prism(const Faces& f, int v[6])
{
    return prismVertices(f.start.data(), f.size(), f.points.data(), v);
}

bool hexahedron(const Faces& f, int v[8])
{
    return hexahedronVertices(f.start.data(), f.size(), f.points.data(), v);
}

} // namespace


TEST(CellShapes, TetrahedronFromItsFaces)
{
    const Faces f({{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
    int v[4];
    ASSERT_TRUE(tetrahedronVertices(f.start.data(), f.size(), f.points.data(), v));
    EXPECT_EQ(std::vector<int>(v, v + 4), (std::vector<int>{0, 2, 1, 3}));

    const Faces quad({{0, 2, 1, 4}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
    EXPECT_FALSE(tetrahedronVertices(quad.start.data(), quad.size(), quad.points.data(), v));
    const Faces repeated({{0, 0, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
    EXPECT_FALSE(tetrahedronVertices(repeated.start.data(), repeated.size(), repeated.points.data(), v));
}


TEST(CellShapes, PrismVerticesAboveTheirTriangle)
{
    // bottom 0 1 2, top 10 11 12 (10 above 0, ...), faces in any order,
    // orientation and first point
    std::vector<std::vector<int>> faces =
    {
        {0, 2, 1}, {10, 11, 12}, {0, 1, 11, 10}, {1, 2, 12, 11}, {2, 0, 10, 12}
    };
    for (int r = 0; r < 5; ++r)
    {
        std::rotate(faces.begin(), faces.begin() + 1, faces.end());
        std::reverse(faces[r].begin(), faces[r].end());
        std::rotate(faces[(r + 2) % 5].begin(), faces[(r + 2) % 5].begin() + 1, faces[(r + 2) % 5].end());
        int v[6];
        ASSERT_TRUE(prism(Faces(faces), v)) << r;
        for (int i = 0; i < 3; ++i)
        {
            // the point above v[i] is v[i] + 10 (or below: the first
            // triangle found may be the top)
            EXPECT_EQ(std::abs(v[3 + i] - v[i]), 10) << r << ' ' << i;
        }
        // v0 v1 v2 one triangle
        EXPECT_TRUE((v[0] < 10) == (v[1] < 10) && (v[1] < 10) == (v[2] < 10));
    }
}


TEST(CellShapes, NotAPrism)
{
    int v[6];
    // a twisted quadrilateral (0 1 10 11: its edges cross)
    EXPECT_FALSE(prism(Faces({{0, 2, 1}, {10, 11, 12}, {0, 1, 10, 11}, {1, 2, 12, 11}, {2, 0, 10, 12}}), v));
    // a quadrilateral joining the triangles' points crosswise
    EXPECT_FALSE(prism(Faces({{0, 2, 1}, {10, 11, 12}, {0, 1, 12, 10}, {1, 2, 10, 11}, {2, 0, 11, 12}}), v));
    // a pyramid: one quadrilateral, four triangles
    EXPECT_FALSE(prism(Faces({{0, 1, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}), v));
    // the triangles share a point
    EXPECT_FALSE(prism(Faces({{0, 2, 1}, {0, 11, 12}, {0, 1, 11, 0}, {1, 2, 12, 11}, {2, 0, 0, 12}}), v));
    // a hexahedron
    EXPECT_FALSE(prism(Faces({{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6},
                              {0, 4, 7, 3}, {1, 2, 6, 5}}), v));
}


TEST(CellShapes, HexahedronVerticesJoinedToTheirFace)
{
    // bottom 0 1 2 3, top 10 11 12 13 (10 above 0, ...), faces in any
    // order, orientation and first point
    std::vector<std::vector<int>> faces =
    {
        {0, 3, 2, 1}, {10, 11, 12, 13}, {0, 1, 11, 10}, {1, 2, 12, 11},
        {2, 3, 13, 12}, {3, 0, 10, 13}
    };
    for (int r = 0; r < 6; ++r)
    {
        std::rotate(faces.begin(), faces.begin() + 1, faces.end());
        std::reverse(faces[r].begin(), faces[r].end());
        std::rotate(faces[(r + 2) % 6].begin(), faces[(r + 2) % 6].begin() + 1, faces[(r + 2) % 6].end());
        int v[8];
        ASSERT_TRUE(hexahedron(Faces(faces), v)) << r;
        for (int i = 0; i < 4; ++i)
        {
            // the point joined to v[i] is v[i] +- 10: the first face is
            // the bottom, the top or a side
            EXPECT_TRUE(std::abs(v[4 + i] - v[i]) == 10 || std::abs(v[4 + i] - v[i]) == 1
                     || std::abs(v[4 + i] - v[i]) == 3) << r << ' ' << i;
        }
        // the first face is a face, the four points joined to it the
        // opposite one
        std::vector<int> first(v, v + 4), second(v + 4, v + 8);
        std::sort(first.begin(), first.end());
        std::sort(second.begin(), second.end());
        bool firstIsAFace = false, secondIsAFace = false;
        for (auto f : faces)
        {
            std::sort(f.begin(), f.end());
            firstIsAFace = firstIsAFace || f == first;
            secondIsAFace = secondIsAFace || f == second;
        }
        EXPECT_TRUE(firstIsAFace && secondIsAFace) << r;
    }
}


TEST(CellShapes, NotAHexahedron)
{
    int v[8];
    // a twisted side (0 1 10 11: its edges cross)
    EXPECT_FALSE(hexahedron(Faces({{0, 3, 2, 1}, {10, 11, 12, 13}, {0, 1, 10, 11}, {1, 2, 12, 11},
                                   {2, 3, 13, 12}, {3, 0, 10, 13}}), v));
    // a point of the bottom joined to two of the top's (0 to 10 and 11)
    EXPECT_FALSE(hexahedron(Faces({{0, 3, 2, 1}, {10, 11, 12, 13}, {0, 1, 11, 10}, {1, 2, 12, 11},
                                   {2, 3, 13, 12}, {3, 0, 11, 13}}), v));
    // a prism
    EXPECT_FALSE(hexahedron(Faces({{0, 2, 1}, {10, 11, 12}, {0, 1, 11, 10}, {1, 2, 12, 11},
                                   {2, 0, 10, 12}}), v));
    // six quadrilaterals with a repeated point
    EXPECT_FALSE(hexahedron(Faces({{0, 3, 2, 1}, {10, 11, 12, 12}, {0, 1, 11, 10}, {1, 2, 12, 11},
                                   {2, 3, 12, 12}, {3, 0, 10, 12}}), v));
    // a cell split by a face into a polyhedron (seven faces)
    EXPECT_FALSE(hexahedron(Faces({{0, 3, 2, 1}, {10, 11, 12, 13}, {0, 1, 11, 10}, {1, 2, 12, 11},
                                   {2, 3, 13, 12}, {3, 0, 10, 13}, {0, 1, 2, 3}}), v));
}
