// One strike of solid fracture computed without touching the mesh (fracture_solid_strike.cpp):
// the region's faces, the pieces clipped and capped, and the bonds.
#include "algorithms/fracture_solid_strike.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/locate.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/core/build.h"
#include "test_meshes.h"

namespace hedge::solid_detail {
namespace {

//! A strike's setting on `mesh` about `centre`, with a break radius in model units.
struct Setting {
  FaceBvh tree;
  SolidFractureOptions options;
  StrikeInput in;
  Setting(SurfaceMesh& mesh, const Vec3d& centre, double radius, const char* material)
      : tree(mesh),
        options{.material = fracture_material(material), .radius = radius},
        in{mesh, tree, centre, 0, fracture_material_at_radius(options.material, radius), options} {
    in.region_radius = radius + 0.5 * in.material.rings.back().spacing;
  }
};

double triangle_area_of(const KeyedSurface& s, std::size_t i) {
  const auto& t = s.tris[i];
  return triangle_area(s.points[s.index(t[0])].second, s.points[s.index(t[1])].second,
                       s.points[s.index(t[2])].second);
}

SurfaceMesh sphere() {
  SurfaceMesh m = build(test::cube());
  subdivide(m, Subdivision::catmull_clark, 3);
  return m;
}

TEST(FractureSolidStrike, RegionFacesAreThoseWhoseBoxMeetsTheRegionsBox) {
  SurfaceMesh m = sphere();
  const Vec3d c = to_double(m.position(Vertex(3)));
  Setting s(m, c, 0.2, "glass");
  std::vector<Face> faces;
  region_faces(s.in, faces);
  ASSERT_FALSE(faces.empty());
  EXPECT_TRUE(std::is_sorted(faces.begin(), faces.end()));
  const double r = s.in.region_radius;
  std::size_t expected = 0;
  for (Face f : m.faces()) {
    bool meets = true;
    for (int a = 0; a < 3 && meets; ++a) {
      float lo = 1e30f, hi = -1e30f;
      for (Vertex v : m.vertices(f)) lo = std::min(lo, m.position(v)[a]), hi = std::max(hi, m.position(v)[a]);
      meets = hi >= c[a] - r && lo <= c[a] + r;
    }
    if (meets) {
      ++expected;
      EXPECT_TRUE(std::binary_search(faces.begin(), faces.end(), f)) << f.idx();
    }
  }
  EXPECT_EQ(faces.size(), expected);
  EXPECT_LT(faces.size(), m.n_faces());  // local: not the whole mesh
}

TEST(FractureSolidStrike, PiecesAreClosedAndTheirTrianglesLieOnTheirSources) {
  SurfaceMesh m = sphere();
  const std::size_t faces_before = m.n_faces();
  Setting s(m, to_double(m.position(Vertex(3))), 0.3, "stone");
  std::vector<Face> faces;
  region_faces(s.in, faces);
  Strike strike;
  ASSERT_TRUE(compute_strike(s.in, faces, 0.0, 11, strike)) << strike.failure;
  ASSERT_GT(strike.pieces.size(), 1u);
  EXPECT_EQ(m.n_faces(), faces_before);  // nothing touched
  EXPECT_TRUE(m.validate().empty());
  const double scale = s.in.region_radius;
  for (const PieceDraft& d : strike.pieces) {
    EXPECT_EQ(d.mesh.n_faces(), d.surface.tris.size());
    for (Halfedge h : d.mesh.halfedges()) EXPECT_FALSE(d.mesh.is_boundary(h));
    EXPECT_TRUE(d.mesh.validate().empty());
    EXPECT_GT(volume(d.mesh), 0);
    std::size_t caps = 0;
    for (std::size_t i = 0; i < d.surface.tris.size(); ++i) {
      const std::uint32_t from = d.surface.source[i];
      for (const Key& k : d.surface.tris[i]) {
        const Vec3d x = d.surface.points[d.surface.index(k)].second;
        if (from & kCapBit) {
          // On its plane, within rounding.
          const Plane& p = strike.planes.planes[from & ~kCapBit];
          EXPECT_NEAR(p.value(x) / norm(p.n), 0, 1e-9 * scale);
        } else {
          // In the plane of its soup triangle.
          const SoupTriangle& t = strike.soup[from];
          const Vec3d a = to_double(m.position(Vertex(t.v[0])));
          const Vec3d n = normalize(
              cross(to_double(m.position(Vertex(t.v[1]))) - a, to_double(m.position(Vertex(t.v[2]))) - a));
          EXPECT_NEAR(dot(x - a, n), 0, 1e-9 * scale);
        }
      }
      caps += (from & kCapBit) != 0;
    }
    EXPECT_GT(caps, 0u);
  }
}

TEST(FractureSolidStrike, BondsAreTheCapAreaTwoPiecesShare) {
  SurfaceMesh m = sphere();
  Setting s(m, to_double(m.position(Vertex(3))), 0.3, "stone");
  std::vector<Face> faces;
  region_faces(s.in, faces);
  Strike strike;
  ASSERT_TRUE(compute_strike(s.in, faces, 0.0, 11, strike)) << strike.failure;
  ASSERT_FALSE(strike.bonds.empty());
  // A bisector's caps in the two pieces on its sides have the same area; the bond is that area.
  std::map<std::pair<std::size_t, std::uint32_t>, double> area;  // (piece, plane) -> cap area
  for (std::size_t p = 0; p < strike.pieces.size(); ++p) {
    const KeyedSurface& su = strike.pieces[p].surface;
    for (std::size_t i = 0; i < su.tris.size(); ++i)
      if (su.source[i] & kCapBit) area[{p, su.source[i] & ~kCapBit}] += triangle_area_of(su, i);
  }
  std::set<std::pair<std::size_t, std::size_t>> seen;
  for (const SolidBond& b : strike.bonds) {
    EXPECT_TRUE(seen.insert({b.a, b.b}).second);
    if (b.b == kSolidRemaining) continue;
    const auto [i, j] = std::minmax(strike.pieces[b.a].cell, strike.pieces[b.b].cell);
    const std::uint32_t plane = strike.planes.bisector_of.at({std::uint32_t(i), std::uint32_t(j)});
    EXPECT_NEAR((area[{b.a, plane}]), b.area, 1e-9 * b.area);
    EXPECT_NEAR((area[{b.b, plane}]), b.area, 1e-9 * b.area);
  }
  // The caps on the region's planes are what the pieces share with the remaining object.
  double to_remaining = 0, on_region = 0;
  for (const SolidBond& b : strike.bonds)
    if (b.b == kSolidRemaining) to_remaining += b.area;
  for (const auto& [key, a] : area)
    if (strike.planes.pair_of[key.second].first < 0) on_region += a;
  EXPECT_GT(on_region, 0);
  EXPECT_NEAR(to_remaining, on_region, 1e-9 * on_region);
}

TEST(FractureSolidStrike, SameInputSameStrikeAndANudgeMovesIt) {
  SurfaceMesh m = sphere();
  Setting s(m, to_double(m.position(Vertex(3))), 0.3, "glass");
  std::vector<Face> faces;
  region_faces(s.in, faces);
  Strike a, b, c;
  ASSERT_TRUE(compute_strike(s.in, faces, 0.0, 5, a));
  ASSERT_TRUE(compute_strike(s.in, faces, 0.0, 5, b));
  ASSERT_TRUE(compute_strike(s.in, faces, 1e-5 * 0.3, 6, c));
  ASSERT_EQ(a.pieces.size(), b.pieces.size());
  for (std::size_t p = 0; p < a.pieces.size(); ++p) {
    EXPECT_EQ(a.pieces[p].surface.tris, b.pieces[p].surface.tris);
    ASSERT_EQ(a.pieces[p].surface.points.size(), b.pieces[p].surface.points.size());
    for (std::size_t i = 0; i < a.pieces[p].surface.points.size(); ++i)
      EXPECT_EQ(a.pieces[p].surface.points[i].second, b.pieces[p].surface.points[i].second);
  }
  EXPECT_EQ(a.patch.tris, b.patch.tris);
  bool moved = a.pieces.size() != c.pieces.size() || a.planes.planes.size() != c.planes.planes.size();
  for (std::size_t i = 0; i < std::min(a.planes.planes.size(), c.planes.planes.size()) && !moved; ++i)
    moved = a.planes.planes[i].d != c.planes.planes[i].d;
  EXPECT_TRUE(moved);
}

}  // namespace
}  // namespace hedge::solid_detail
