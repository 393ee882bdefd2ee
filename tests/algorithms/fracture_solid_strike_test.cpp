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

//! A keyed surface of triangles over points 0..n-1 at `pos`, each point listed once per triangle
//! that uses it, in reverse order (as a piece lists a point once per polygon around it).
KeyedSurface keyed(const std::vector<Vec3d>& pos, const std::vector<std::array<std::uint32_t, 3>>& tris) {
  KeyedSurface s;
  auto key = [](std::uint32_t i) { return Key{Key::vertex, i, 0, 0}; };
  for (const auto& t : tris) {
    s.add({key(t[0]), key(t[1]), key(t[2])}, 0);
    for (int k = 2; k >= 0; --k) s.points.emplace_back(key(t[k]), pos[t[k]]);
  }
  std::reverse(s.points.begin(), s.points.end());
  return s;
}

const std::vector<Vec3d> kOctahedron{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
const std::vector<std::array<std::uint32_t, 3>> kOctahedronFaces{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                                                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};

TEST(FractureSolidStrike, BuildClosedLinksAPieceAsBuildTrianglesWould) {
  // Points numbered 4..9 in key order, so that a corner's point differs from its input number.
  std::vector<Vec3d> pos(10);
  std::vector<std::array<std::uint32_t, 3>> tris;
  for (std::size_t i = 0; i < 6; ++i) pos[i + 4] = kOctahedron[i];
  for (const auto& t : kOctahedronFaces) tris.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  KeyedSurface s = keyed(pos, tris);
  SurfaceMesh mesh;
  std::vector<std::uint32_t> corner;
  std::string failure;
  ASSERT_TRUE(build_closed(s, mesh, corner, failure)) << failure;
  EXPECT_TRUE(mesh.validate().empty());
  ASSERT_EQ(s.points.size(), 6u);
  ASSERT_EQ(corner.size(), 3 * tris.size());
  for (std::size_t c = 0; c < corner.size(); ++c) EXPECT_EQ(corner[c], tris[c / 3][c % 3] - 4);
  std::vector<Vec3> positions;
  for (const Vec3d& p : kOctahedron) positions.push_back(to_float(p));
  std::vector<std::uint32_t> indices(corner.begin(), corner.end());
  BuildOptions bo;
  bo.corner_attributes = false;
  const SurfaceMesh expected = build_triangles(positions, indices, bo);
  ASSERT_EQ(mesh.halfedge_slots(), expected.halfedge_slots());
  ASSERT_EQ(mesh.vertex_slots(), expected.vertex_slots());
  ASSERT_EQ(mesh.face_slots(), expected.face_slots());
  for (Index h = 0; h < mesh.halfedge_slots(); ++h) {
    EXPECT_EQ(mesh.to_vertex(Halfedge(h)), expected.to_vertex(Halfedge(h)));
    EXPECT_EQ(mesh.next(Halfedge(h)), expected.next(Halfedge(h)));
    EXPECT_EQ(mesh.face(Halfedge(h)), expected.face(Halfedge(h)));
  }
  for (Index v = 0; v < mesh.vertex_slots(); ++v) {
    EXPECT_EQ(mesh.halfedge(Vertex(v)), expected.halfedge(Vertex(v)));
    EXPECT_EQ(mesh.position(Vertex(v)), expected.position(Vertex(v)));
  }
  for (Index f = 0; f < mesh.face_slots(); ++f) EXPECT_EQ(mesh.halfedge(Face(f)), expected.halfedge(Face(f)));
}

TEST(FractureSolidStrike, BuildClosedRefusesOpenNonManifoldAndPinchedPieces) {
  auto refusal = [](const std::vector<Vec3d>& pos, std::vector<std::array<std::uint32_t, 3>> tris) {
    KeyedSurface s = keyed(pos, tris);
    SurfaceMesh mesh;
    std::vector<std::uint32_t> corner;
    std::string failure;
    return build_closed(s, mesh, corner, failure) ? std::string() : failure;
  };
  auto faces = kOctahedronFaces;
  EXPECT_EQ(refusal(kOctahedron, faces), "");
  faces.pop_back();
  EXPECT_NE(refusal(kOctahedron, faces).find("a piece is open"), std::string::npos);
  faces = kOctahedronFaces;
  faces.push_back(faces[0]);
  EXPECT_NE(refusal(kOctahedron, faces).find("the same way"), std::string::npos);
  faces = kOctahedronFaces;
  faces[0] = {0, 2, 2};
  EXPECT_NE(refusal(kOctahedron, faces).find("repeats a point"), std::string::npos);
  // Two octahedra sharing point 0: every edge is used twice, but point 0 has two fans.
  std::vector<Vec3d> pos = kOctahedron;
  for (std::size_t i = 1; i < 6; ++i) pos.push_back(kOctahedron[i] + Vec3d{2, 0, 0});
  faces = kOctahedronFaces;
  for (const auto& t : kOctahedronFaces) {
    std::array<std::uint32_t, 3> u;
    for (int k = 0; k < 3; ++k) u[k] = t[k] == 1 ? 0 : t[k] == 0 ? 6 : t[k] + 5;
    faces.push_back(u);
  }
  // The second one's point 1 (at x = 1) is renumbered to the first's point 0; its own point 0 (at
  // x = 3) becomes 6.
  pos[6] = Vec3d{3, 0, 0};
  EXPECT_NE(refusal(pos, faces).find("more than one fan"), std::string::npos);
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
