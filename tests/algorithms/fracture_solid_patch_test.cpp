// The patch of solid fracture's remaining object (fracture_solid_patch.cpp): the touched triangles'
// parts outside the region, checked to fit the hole before the mesh is touched.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "algorithms/fracture_solid_strike.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/locate.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/core/build.h"
#include "test_meshes.h"

namespace hedge::solid_detail {
namespace {

struct Setting {
  FaceBvh tree;
  SolidFractureOptions options;
  StrikeInput in;
  Setting(SurfaceMesh& mesh, const Vec3d& centre, double radius)
      : tree(mesh),
        options{.material = fracture_material("stone"), .radius = radius},
        in{mesh, tree, centre, 0, fracture_material_at_radius(options.material, radius), options} {
    in.region_radius = radius + 0.5 * in.material.rings.back().spacing;
  }
};

double area_of(const KeyedSurface& s, std::size_t i) {
  const auto& t = s.tris[i];
  return triangle_area(s.points[s.index(t[0])].second, s.points[s.index(t[1])].second,
                       s.points[s.index(t[2])].second);
}

TEST(FractureSolidPatch, EachTouchedTriangleIsSplitBetweenThePiecesAndThePatch) {
  SurfaceMesh m = build(test::cube());
  subdivide(m, Subdivision::catmull_clark, 3);
  Setting s(m, to_double(m.position(Vertex(3))), 0.3);
  std::vector<Face> faces;
  region_faces(s.in, faces);
  Strike strike;
  ASSERT_TRUE(compute_strike(s.in, faces, 0.0, 11, strike)) << strike.failure;
  ASSERT_FALSE(strike.touched.empty());
  EXPECT_TRUE(std::is_sorted(strike.touched.begin(), strike.touched.end()));
  // Per soup triangle: its area inside the region (in the pieces) and outside (in the patch).
  std::map<std::uint32_t, double> inside, outside;
  for (const PieceDraft& d : strike.pieces)
    for (std::size_t i = 0; i < d.surface.tris.size(); ++i)
      if (!(d.surface.source[i] & kCapBit)) inside[d.surface.source[i]] += area_of(d.surface, i);
  double caps = 0;
  for (std::size_t i = 0; i < strike.patch.tris.size(); ++i)
    if (strike.patch.source[i] & kCapBit)
      caps += area_of(strike.patch, i);
    else
      outside[strike.patch.source[i]] += area_of(strike.patch, i);
  EXPECT_GT(caps, 0);
  std::size_t split = 0;
  for (std::uint32_t t = 0; t < strike.soup.size(); ++t) {
    const SoupTriangle& st = strike.soup[t];
    if (!std::binary_search(strike.touched.begin(), strike.touched.end(), st.face)) continue;
    const double whole =
        triangle_area(to_double(m.position(Vertex(st.v[0]))), to_double(m.position(Vertex(st.v[1]))),
                      to_double(m.position(Vertex(st.v[2]))));
    EXPECT_NEAR(inside[t] + outside[t], whole, 1e-9 * whole) << "soup triangle " << t;
    split += inside[t] > 0 && outside[t] > 0;
  }
  EXPECT_GT(split, 0u);  // the region's boundary crosses triangles
  // The patch's edges without a twin in it are the hole's rim: edges of the mesh between a
  // touched face and one that stays.
  std::vector<std::pair<Key, Key>> edges;
  for (const auto& t : strike.patch.tris)
    for (int i = 0; i < 3; ++i) edges.emplace_back(t[i], t[(i + 1) % 3]);
  std::sort(edges.begin(), edges.end());
  std::size_t rim = 0;
  for (const auto& [a, b] : edges)
    if (!std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a))) {
      ASSERT_EQ(a.kind, Key::vertex);
      ASSERT_EQ(b.kind, Key::vertex);
      const Halfedge h = m.find_halfedge(Vertex(b.a), Vertex(a.a));
      ASSERT_TRUE(h.is_valid());
      EXPECT_FALSE(std::binary_search(strike.touched.begin(), strike.touched.end(), m.face(h)));
      ++rim;
    }
  EXPECT_GT(rim, 0u);
  EXPECT_TRUE(m.validate().empty());
}

//! A triangulated cube's soup, every face's triangle taken as it is (fan of a triangle).
std::vector<SoupTriangle> soup_of(const SurfaceMesh& m) {
  std::vector<SoupTriangle> soup;
  for (Face f : m.faces()) {
    SoupTriangle s;
    s.face = f;
    int k = 0;
    for (Halfedge h : m.halfedges(f)) {
      s.corner[k] = h;
      s.v[k] = m.to_vertex(h).idx();
      ++k;
    }
    soup.push_back(s);
  }
  return soup;
}

TEST(FractureSolidPatch, FacesThatWouldPinchAVertexAreTouchedAndAnOpenPatchIsRefused) {
  // The cube's quads split into triangles.
  const IndexedMesh quads = test::cube();
  IndexedMesh cube;
  cube.positions = quads.positions;
  for (std::size_t q = 0; q < quads.face_sizes.size(); ++q) {
    const std::uint32_t* c = &quads.indices[4 * q];
    cube.indices.insert(cube.indices.end(), {c[0], c[1], c[2], c[0], c[2], c[3]});
    cube.face_sizes.insert(cube.face_sizes.end(), {3, 3});
  }
  SurfaceMesh m = build(cube);
  Setting s(m, {0.5, 0.5, 0.5}, 0.1);
  Strike strike;
  strike.soup = soup_of(m);
  const Geometry g{&m, &strike.planes, &strike.soup, nullptr};
  // Two faces that share only vertex v, apart in its fan: removing them would leave v between two
  // fans of faces, so every face around v joins them.
  Vertex v;
  std::vector<Face> around;
  for (Vertex w : m.vertices()) {
    std::vector<Face> fs;
    for (Face f : m.faces(w)) fs.push_back(f);
    if (fs.size() > around.size()) v = w, around = fs;
  }
  ASSERT_GE(around.size(), 4u);
  const Face a = around[0], b = around[2];
  std::vector<ClipPolygon> inside_p(strike.soup.size());
  std::vector<char> touched(strike.soup.size(), 0);
  for (std::uint32_t t = 0; t < strike.soup.size(); ++t)
    if (strike.soup[t].face == a || strike.soup[t].face == b) {
      touched[t] = 1;
      // Wholly inside the region: no edge of it on a plane.
      for (int k = 0; k < 3; ++k) {
        inside_p[t].keys.push_back({Key::vertex, strike.soup[t].v[k], 0, 0});
        inside_p[t].pos.push_back(g.vertex(strike.soup[t].v[k]));
        inside_p[t].support.push_back(kNoPlane);
      }
    }
  const std::size_t faces = m.n_faces();
  // Nothing caps the region, so the hole of a and b stays open: refused.
  EXPECT_FALSE(patch_outside(s.in, g, inside_p, touched, strike));
  EXPECT_FALSE(strike.failure.empty());
  for (Face f : around) EXPECT_TRUE(std::binary_search(strike.touched.begin(), strike.touched.end(), f));
  EXPECT_EQ(m.n_faces(), faces);
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge::solid_detail
