// The soup of solid fracture (fracture_solid_soup.cpp): the region's faces as triangles, the grid
// that hands a box its triangles, and the numbering of the soup's vertices.
#include "algorithms/fracture_solid_soup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "hedge/core/build.h"
#include "test_meshes.h"

namespace hedge::solid_detail {
namespace {

std::vector<Face> all_faces(const SurfaceMesh& m) {
  std::vector<Face> faces;
  for (Face f : m.faces()) faces.push_back(f);
  return faces;
}

TEST(FractureSolidSoup, QuadsBecomeTwoTrianglesEachWithTheirCornersAndBoxes) {
  const SurfaceMesh m = build(test::cube());  // six quads
  const std::vector<SoupTriangle> soup = make_soup(m, all_faces(m));
  ASSERT_EQ(soup.size(), 12u);
  for (std::size_t t = 0; t < soup.size(); ++t) {
    EXPECT_EQ(soup[t].face, Face(static_cast<Index>(t / 2)));
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(m.face(soup[t].corner[k]), soup[t].face);
      EXPECT_EQ(m.to_vertex(soup[t].corner[k]).idx(), soup[t].v[k]);
      const Vec3& p = m.position(Vertex(soup[t].v[k]));
      for (int a = 0; a < 3; ++a) {
        EXPECT_LE(soup[t].lo[a], p[a]);
        EXPECT_GE(soup[t].hi[a], p[a]);
      }
    }
    // The box is the corners' own: each bound is one corner's coordinate.
    for (int a = 0; a < 3; ++a) {
      bool lo = false, hi = false;
      for (int k = 0; k < 3; ++k) {
        lo |= m.position(Vertex(soup[t].v[k]))[a] == soup[t].lo[a];
        hi |= m.position(Vertex(soup[t].v[k]))[a] == soup[t].hi[a];
      }
      EXPECT_TRUE(lo && hi) << t;
    }
  }
}

TEST(FractureSolidSoup, TheGridListsEveryTriangleWhoseBoxMeetsAQueryBoxInOrder) {
  const SurfaceMesh m = build(test::triangle_lattice(24));
  const std::vector<SoupTriangle> soup = make_soup(m, all_faces(m));
  const SoupGrid grid = grid_soup(soup);
  EXPECT_GT(grid.n[0] * grid.n[1] * grid.n[2], 1);
  for (std::size_t b = 0; b + 1 < grid.first.size(); ++b)
    EXPECT_TRUE(std::is_sorted(grid.items.begin() + grid.first[b], grid.items.begin() + grid.first[b + 1]));
  float lo0[3], hi0[3];
  for (int a = 0; a < 3; ++a) {
    lo0[a] = soup[0].lo[a];
    hi0[a] = soup[0].hi[a];
  }
  for (const SoupTriangle& t : soup)
    for (int a = 0; a < 3; ++a) {
      lo0[a] = std::min(lo0[a], t.lo[a]);
      hi0[a] = std::max(hi0[a], t.hi[a]);
    }
  // Boxes across the lattice, from a sliver to more than the whole.
  for (int q = 0; q < 40; ++q) {
    float lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      const float w = hi0[a] - lo0[a];
      lo[a] = lo0[a] + w * (0.023f * q - 0.1f);
      hi[a] = lo[a] + w * (0.01f + 0.03f * (q % 7));
    }
    std::set<std::uint32_t> listed;
    grid.for_buckets(lo, hi, [&](std::size_t b) {
      for (std::uint32_t i = grid.first[b]; i < grid.first[b + 1]; ++i) listed.insert(grid.items[i]);
    });
    for (std::uint32_t t = 0; t < soup.size(); ++t)
      if (overlaps(soup[t], lo, hi)) EXPECT_TRUE(listed.count(t)) << "query " << q << " triangle " << t;
  }
}

TEST(FractureSolidSoup, VerticesAreNumberedInTheOrderOfFirstUse) {
  const SurfaceMesh m = build(test::cube());
  const std::vector<SoupTriangle> soup = make_soup(m, all_faces(m));
  const SoupIndex x = index_soup(soup);
  ASSERT_EQ(x.vertices.size(), 8u);
  EXPECT_EQ(std::set<Index>(x.vertices.begin(), x.vertices.end()).size(), 8u);
  std::vector<Index> seen;
  for (std::size_t t = 0; t < soup.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(x.vertices[x.corner[t][k]], soup[t].v[k]);
      if (std::find(seen.begin(), seen.end(), soup[t].v[k]) == seen.end()) seen.push_back(soup[t].v[k]);
    }
  EXPECT_EQ(seen, x.vertices);
}

TEST(FractureSolidSoup, NumberTableKeepsTheFirstNumberOfEachValue) {
  NumberTable<Index, HashIndex> table(3);
  EXPECT_EQ(table.find(7), (NumberTable<Index, HashIndex>::kAbsent));
  EXPECT_EQ(table.find_or_add(7, 0), 0u);
  EXPECT_EQ(table.find_or_add(9, 1), 1u);
  EXPECT_EQ(table.find_or_add(7, 2), 0u);
  EXPECT_EQ(table.find(9), 1u);
  KeyTable keys(2);
  const Key a{Key::edge, 1, 2, 3}, b{Key::edge, 1, 2, 4};
  EXPECT_EQ(keys.find_or_add(a, 5), 5u);
  EXPECT_EQ(keys.find(b), KeyTable::kAbsent);
  EXPECT_EQ(keys.find_or_add(b, 6), 6u);
  EXPECT_EQ(keys.find(a), 5u);
}

}  // namespace
}  // namespace hedge::solid_detail
