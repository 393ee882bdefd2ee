#include "hedge/algorithms/mirror.h"

#include <gtest/gtest.h>

#include <vector>

#include "hedge/core/build.h"
#include "hedge/core/edge_operations.h"
#include "hedge/render/engine_mesh.h"
#include "test_meshes.h"

namespace hedge {
namespace {

// An open, asymmetric fan: a long arm at x = +3, so that a mirror cannot pass for the identity;
// per-vertex texcoords and normals that differ at every vertex, welded apex seam (vertices 4, 5).
SurfaceMesh asymmetric() {
  const std::vector<Vec3> p = {{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {0, 1, 0}, {0.5f, 0.5f, 1}, {0.5f, 0.5f, 1}};
  const std::vector<std::uint32_t> t = {0, 1, 4, 1, 2, 4, 2, 3, 5, 3, 0, 5};
  std::vector<Vec3> n;
  std::vector<Vec2> uv;
  for (std::size_t i = 0; i < p.size(); ++i) {
    n.push_back(normalize(Vec3{0.1f * float(i + 1), 0.2f, 1}));
    uv.push_back({0.125f * float(i), 1 - 0.0625f * float(i)});
  }
  SurfaceMesh m = from_engine_mesh({p, t, n, uv, {}});
  auto vn = m.add_vertex_property<Vec3>("v:normal");
  for (Vertex v : m.vertices()) vn[v] = normalize(Vec3{1, 2, 3} + m.position(v));
  return m;
}

// Each face's corners, in order, as (vertex, texcoord, normal).
struct Corner {
  Vertex v;
  Vec2 uv;
  Vec3 n;
};
std::vector<std::vector<Corner>> corners(const SurfaceMesh& m) {
  auto uv = m.get_halfedge_property<Vec2>("h:texcoord");
  auto n = m.get_halfedge_property<Vec3>("h:normal");
  std::vector<std::vector<Corner>> out;
  for (Face f : m.faces()) {
    out.emplace_back();
    for (Halfedge h : m.halfedges(f)) out.back().push_back({m.to_vertex(h), uv[h], n[h]});
  }
  return out;
}

TEST(Mirror, NegatesXAndReversesFacesKeepingCornerAttributes) {
  SurfaceMesh m = asymmetric();
  const SurfaceMesh before = m;
  const auto old_corners = corners(m);
  mirror_x(m);
  EXPECT_TRUE(m.validate().empty());
  ASSERT_EQ(m.n_vertices(), before.n_vertices());
  for (Vertex v : m.vertices()) {
    const Vec3 a = before.position(v), b = m.position(v);
    EXPECT_EQ(b.x, -a.x);
    EXPECT_EQ(b.y, a.y);
    EXPECT_EQ(b.z, a.z);
    const Vec3 na = before.get_vertex_property<Vec3>("v:normal")[v],
               nb = m.get_vertex_property<Vec3>("v:normal")[v];
    EXPECT_EQ(nb.x, -na.x);
    EXPECT_EQ(nb.y, na.y);
  }
  const Vertex arm = Vertex(1);
  EXPECT_EQ(m.position(arm).x, -3.f);
  // Each face lists the same corners in reverse order, each with its own texcoord, and its normal
  // mirrored.
  const auto new_corners = corners(m);
  ASSERT_EQ(new_corners.size(), old_corners.size());
  for (std::size_t f = 0; f < new_corners.size(); ++f) {
    const auto& o = old_corners[f];
    const auto& c = new_corners[f];
    ASSERT_EQ(c.size(), o.size());
    std::size_t start = 0;
    while (start < o.size() && o[start].v != c[0].v) ++start;
    ASSERT_LT(start, o.size());
    for (std::size_t i = 0; i < c.size(); ++i) {
      const Corner& was = o[(start + o.size() - i) % o.size()];
      EXPECT_EQ(c[i].v, was.v) << "face " << f << " corner " << i;
      EXPECT_EQ(c[i].uv, was.uv) << "face " << f << " corner " << i;
      EXPECT_EQ(c[i].n, (Vec3{-was.n.x, was.n.y, was.n.z})) << "face " << f << " corner " << i;
    }
  }
  // The faces face the mirrored way: face normals are mirrored too (the apex faces point up still).
  for (Face f : m.faces()) {
    std::vector<Vec3> p;
    for (Vertex v : m.vertices(f)) p.push_back(m.position(v));
    EXPECT_GT(cross(p[1] - p[0], p[2] - p[0]).z, 0) << "face " << f.idx();
  }
}

TEST(Mirror, TwiceIsTheIdentityBitForBit) {
  SurfaceMesh m = asymmetric();
  const auto old_corners = corners(m);
  std::vector<Vertex> to;
  std::vector<Halfedge> next;
  for (Halfedge h : m.halfedges()) {
    to.push_back(m.to_vertex(h));
    next.push_back(m.next(h));
  }
  mirror_x(m);
  mirror_x(m);
  EXPECT_TRUE(m.validate().empty());
  std::size_t i = 0;
  for (Halfedge h : m.halfedges()) {
    EXPECT_EQ(m.to_vertex(h), to[i]);
    EXPECT_EQ(m.next(h), next[i]);
    ++i;
  }
  const auto again = corners(m);
  for (std::size_t f = 0; f < again.size(); ++f)
    for (std::size_t c = 0; c < again[f].size(); ++c) {
      EXPECT_EQ(again[f][c].v, old_corners[f][c].v);
      EXPECT_EQ(again[f][c].uv, old_corners[f][c].uv);
      EXPECT_EQ(again[f][c].n, old_corners[f][c].n);
    }
}

TEST(Mirror, SkipsDeletedElementsAndRecordsAReset) {
  SurfaceMesh m = build(test::grid(3, true));
  const Edge e =
      test::first_edge(m, [&](Edge e) { return !m.is_boundary(e) && can_collapse(m, m.halfedge(e, 0)); });
  ASSERT_TRUE(e.is_valid());
  const Halfedge h = m.halfedge(e, 0);
  ASSERT_TRUE(h.is_valid());
  collapse(m, h);
  ASSERT_GT(m.edge_slots(), m.n_edges());
  auto watch = m.watch_changes();
  const auto id = watch.attach();
  mirror_x(m);
  EXPECT_TRUE(m.validate().empty());
  EXPECT_TRUE(watch.reset_pending(id));
  watch.detach(id);
  mirror_x(m);
  m.garbage_collection();
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge
