// Submeshes in RenderBuffers: each "f:submesh" value is one contiguous index range.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "hedge/algorithms/decimate.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/core/operations.h"
#include "hedge/error.h"
#include "hedge/render/render_buffers.h"
#include "test_meshes.h"

namespace hedge {
namespace {

// A triangulated grid whose faces take submesh 0, 1 or 2 by the column of their centre (and none
// when `submeshes` is 0).
SurfaceMesh grid_with_submeshes(int n, int submeshes = 3) {
  SurfaceMesh m = build(test::grid(n, true));
  if (submeshes == 0) return m;
  auto s = m.add_face_property<std::int32_t>("f:submesh", 0);
  for (Face f : m.faces()) {
    float cx = 0;
    for (Vertex v : m.vertices(f)) cx += m.position(v).x / 3;
    s[f] = std::min(submeshes - 1, static_cast<int>(cx * submeshes / n));
  }
  return m;
}

// Every face's triangles lie in its submesh's range, the ranges are disjoint and in order, and each
// range's vertex range and bounds hold what its live triangles use (the bounds exactly when
// `exact_boxes`: after a full build or compact()).
void expect_submeshes(const RenderBuffers& rs, bool exact_boxes = false) {
  const SurfaceMesh& m = rs.mesh();
  auto prop = m.get_face_property<std::int32_t>("f:submesh");
  const auto ix = rs.indices();
  const std::size_t stride = rs.layout().interleaved ? rs.layout().stride : 3;
  const auto v = rs.vertices();
  std::uint32_t end = 0;
  std::vector<SubmeshRange> ranges;
  for (std::size_t i = 0; i < rs.submesh_count(); ++i) {
    const SubmeshRange r = rs.submesh(i);
    EXPECT_EQ(r.index_start, end) << "submesh " << i;
    end = r.index_start + r.index_count;
    ranges.push_back(r);
  }
  EXPECT_EQ(end, rs.index_count());
  std::vector<Vec3> lo(ranges.size(), Vec3{1e30f, 1e30f, 1e30f}),
      hi(ranges.size(), Vec3{-1e30f, -1e30f, -1e30f});
  std::size_t live = 0;
  for (Face f : m.faces()) {
    const std::size_t s = prop ? static_cast<std::size_t>(std::max(0, prop[f])) : 0;
    ASSERT_LT(s, ranges.size()) << "face " << f.idx();
    EXPECT_EQ(rs.face_submesh(f), s) << "face " << f.idx();
    const SlotRange t = rs.triangles(f);
    ASSERT_EQ(t.count, m.valence(f) - 2) << "face " << f.idx();
    live += t.count;
    EXPECT_GE(3 * t.first, ranges[s].index_start) << "face " << f.idx() << " of submesh " << s;
    EXPECT_LE(3 * (t.first + t.count), ranges[s].index_start + ranges[s].index_count)
        << "face " << f.idx() << " of submesh " << s;
    for (std::uint32_t k = 3 * t.first; k < 3 * (t.first + t.count); ++k) {
      const std::uint32_t rv = ix[k];
      EXPECT_GE(rv, ranges[s].first_vertex);
      EXPECT_LT(rv, ranges[s].first_vertex + ranges[s].vertex_count);
      const float* p = v.data() + rv * stride;
      lo[s] = {std::min(lo[s].x, p[0]), std::min(lo[s].y, p[1]), std::min(lo[s].z, p[2])};
      hi[s] = {std::max(hi[s].x, p[0]), std::max(hi[s].y, p[1]), std::max(hi[s].z, p[2])};
    }
  }
  EXPECT_EQ(live, rs.n_triangles());
  for (std::size_t s = 0; s < ranges.size(); ++s) {
    // Free slots are degenerate and inside the vertex range too.
    for (std::uint32_t k = ranges[s].index_start; k < ranges[s].index_start + ranges[s].index_count; ++k)
      EXPECT_LT(ix[k] - ranges[s].first_vertex, ranges[s].vertex_count) << "index entry " << k;
    if (lo[s].x > hi[s].x) continue;  // no live triangle
    if (exact_boxes) {
      EXPECT_EQ(ranges[s].min, lo[s]) << "submesh " << s;
      EXPECT_EQ(ranges[s].max, hi[s]) << "submesh " << s;
    } else {  // grown by the syncs: around the submesh, maybe larger
      EXPECT_TRUE(ranges[s].min.x <= lo[s].x && ranges[s].min.y <= lo[s].y && ranges[s].min.z <= lo[s].z)
          << "submesh " << s;
      EXPECT_TRUE(ranges[s].max.x >= hi[s].x && ranges[s].max.y >= hi[s].y && ranges[s].max.z >= hi[s].z)
          << "submesh " << s;
    }
  }
  EXPECT_TRUE(m.validate().empty());
}

Vec3 centre(const SurfaceMesh& m, Face f) {
  Vec3 c{0, 0, 0};
  float n = 0;
  for (Vertex v : m.vertices(f)) {
    c = c + m.position(v);
    ++n;
  }
  return c * (1 / n);
}

std::size_t index_entries(const SyncResult& r) {
  std::size_t n = 0;
  for (const SlotRange& s : r.index_ranges) n += s.count;
  return n;
}

TEST(RenderBuffersSubmesh, EachSubmeshIsOneIndexRange) {
  SurfaceMesh m = grid_with_submeshes(8);
  RenderBuffers rs(m);
  ASSERT_EQ(rs.submesh_count(), 3u);
  expect_submeshes(rs, true);
  // The submeshes' boxes are the columns of the grid.
  EXPECT_EQ(rs.submesh(0).min.x, 0.f);
  EXPECT_EQ(rs.submesh(2).max.x, 8.f);
  EXPECT_LT(rs.submesh(0).max.x, rs.submesh(2).min.x);
  EXPECT_THROW(rs.submesh(3), InvalidInputError);
}

TEST(RenderBuffersSubmesh, WithoutThePropertyOneSubmeshCoversTheBuffer) {
  SurfaceMesh m = grid_with_submeshes(4, 0);
  RenderBuffers rs(m);
  ASSERT_EQ(rs.submesh_count(), 1u);
  const SubmeshRange r = rs.submesh(0);
  EXPECT_EQ(r.index_start, 0u);
  EXPECT_EQ(r.index_count, rs.index_count());
  EXPECT_EQ(rs.free_triangle_slots(), 0u);
  expect_submeshes(rs);
}

TEST(RenderBuffersSubmesh, EditsStayInTheirSubmeshAndRewriteLittle) {
  SurfaceMesh m = grid_with_submeshes(12);
  RenderBuffers rs(m);
  std::mt19937 rng(7);
  for (int i = 0; i < 60; ++i) {
    const Edge e(static_cast<Index>(rng() % m.edge_slots()));
    if (m.is_deleted(e)) continue;
    if (i % 3 == 0 && can_split_edge(m, e)) {
      split_edge(m, e,
                 (m.position(m.from_vertex(SurfaceMesh::halfedge(e, 0))) +
                  m.position(m.to_vertex(SurfaceMesh::halfedge(e, 0)))) *
                     0.5f);
    } else if (i % 3 == 1 && can_collapse(m, SurfaceMesh::halfedge(e, 0))) {
      collapse(m, SurfaceMesh::halfedge(e, 0));
    } else if (can_flip(m, e)) {
      flip(m, e);
    }
    const SyncResult& r = rs.sync();
    if (!r.full) EXPECT_LT(index_entries(r), 40u) << "edit " << i;
    expect_submeshes(rs);
  }
  rs.rebuild();
  expect_submeshes(rs, true);
}

// A copy of the buffers that only receives what the syncs report, as a GPU does: after every sync it
// must equal the buffers (vertex data of the live render vertices, every index).
TEST(RenderBuffersSubmesh, TheReportedRangesCoverEveryChange) {
  SurfaceMesh m = grid_with_submeshes(10, 4);
  RenderBuffers rs(m);
  std::vector<float> v(rs.vertices().begin(), rs.vertices().end());
  std::vector<std::uint32_t> ix(rs.indices().begin(), rs.indices().end());
  std::mt19937 rng(11);
  int full = 0;
  for (int i = 0; i < 300; ++i) {
    const Edge e(static_cast<Index>(rng() % m.edge_slots()));
    if (m.is_deleted(e)) continue;
    const Halfedge h = SurfaceMesh::halfedge(e, 0);
    switch (i % 4) {
      case 0:
        if (can_split_edge(m, e))
          split_edge(m, e, (m.position(m.from_vertex(h)) + m.position(m.to_vertex(h))) * 0.5f);
        break;
      case 1:
        if (can_collapse(m, h)) collapse(m, h);
        break;
      case 2:
        if (can_flip(m, e)) flip(m, e);
        break;
      default:
        if (!m.is_boundary(h) && can_split_face(m, m.face(h))) split_face(m, m.face(h), centre(m, m.face(h)));
    }
    const SyncResult& r = rs.sync();
    const auto bv = rs.vertices();
    const auto bi = rs.indices();
    const std::size_t stride = rs.layout().stride;
    if (r.full) {
      ++full;
      v.assign(bv.begin(), bv.end());
      ix.assign(bi.begin(), bi.end());
    }
    v.resize(bv.size(), -1.f);
    ix.resize(bi.size(), 0xdeadbeefu);
    for (const SlotRange& s : r.vertex_ranges)
      std::copy_n(bv.begin() + s.first * stride, s.count * stride, v.begin() + s.first * stride);
    for (const SlotRange& s : r.index_ranges)
      std::copy_n(bi.begin() + s.first, s.count, ix.begin() + s.first);
    ASSERT_TRUE(std::equal(ix.begin(), ix.end(), bi.begin())) << "edit " << i;
    for (std::size_t rv = 0; rv < rs.vertex_slots(); ++rv)
      if (rs.render_vertex_source()[rv].is_valid())
        for (std::size_t k = 0; k < stride; ++k)
          ASSERT_EQ(v[rv * stride + k], bv[rv * stride + k]) << "edit " << i << ", render vertex " << rv;
    expect_submeshes(rs);
  }
  EXPECT_GE(full, 1);  // the splits outgrow some region: the rebuild is exercised too
}

TEST(RenderBuffersSubmesh, ARegionThatOverflowsIsLaidOutAgain) {
  SurfaceMesh m = grid_with_submeshes(8);
  RenderBuffers rs(m);
  const std::size_t room = rs.submesh(0).index_count / 3;
  bool rebuilt = false;
  // Split the faces of submesh 0 until its region has no room left.
  for (std::size_t i = 0; i < room && !rebuilt; ++i) {
    Face f;
    for (Face g : m.faces())
      if (m.get_face_property<std::int32_t>("f:submesh")[g] == 0) f = g;
    split_face(m, f, centre(m, f));
    rebuilt = rs.sync().full;
    expect_submeshes(rs);
  }
  EXPECT_TRUE(rebuilt);
  EXPECT_GT(rs.submesh(0).index_count / 3, room);
}

TEST(RenderBuffersSubmesh, AMovedVertexGrowsTheBoxesOfItsSubmeshesOnly) {
  SurfaceMesh m = grid_with_submeshes(6);
  RenderBuffers rs(m);
  const SubmeshRange before = rs.submesh(0);
  Vertex v;  // an inner vertex of submesh 2 only
  for (Vertex w : m.vertices())
    if (m.position(w).x == 5 && m.position(w).y == 3) v = w;
  ASSERT_TRUE(v.is_valid());
  m.set_position(v, Vec3{5, 3, 2});
  rs.sync();
  EXPECT_EQ(rs.submesh(2).max.z, 2.f);
  EXPECT_EQ(rs.submesh(0).max, before.max);
  m.set_position(v, Vec3{5, 3, 0});
  rs.sync();
  EXPECT_EQ(rs.submesh(2).max.z, 2.f);  // a sync never shrinks a box
  expect_submeshes(rs);
  rs.compact();
  EXPECT_EQ(rs.submesh(2).max.z, 0.f);
  expect_submeshes(rs, true);
}

TEST(RenderBuffersSubmesh, AFaceMovedToAnotherSubmeshMovesItsTriangles) {
  SurfaceMesh m = grid_with_submeshes(6);
  RenderBuffers rs(m);
  auto s = m.get_face_property<std::int32_t>("f:submesh");
  const Face f = *m.faces().begin();
  s[f] = 1;
  m.changes().mark(f, ChangeEvent::faces_changed);
  rs.sync();
  EXPECT_EQ(rs.face_submesh(f), 1u);
  expect_submeshes(rs);
  s[f] = 5;  // a submesh beyond the last region: a full rebuild makes room for it
  m.changes().mark(f, ChangeEvent::faces_changed);
  EXPECT_TRUE(rs.sync().full);
  EXPECT_EQ(rs.submesh_count(), 6u);
  expect_submeshes(rs);
}

TEST(RenderBuffersSubmesh, SubmeshesAddedByAnEditAreGroupedAtTheNextSync) {
  // As solid fracture adds "f:submesh" for its caps to a mesh that had none.
  SurfaceMesh m = grid_with_submeshes(6, 0);
  RenderBuffers rs(m);
  ASSERT_EQ(rs.submesh_count(), 1u);
  auto s = m.add_face_property<std::int32_t>("f:submesh", 0);
  const Face f = *m.faces().begin();
  const Vertex v = split_face(m, f, centre(m, f));
  for (Face g : m.faces(v)) s[g] = 2;
  EXPECT_TRUE(rs.sync().full);
  EXPECT_EQ(rs.submesh_count(), 3u);
  for (Face g : m.faces(v)) EXPECT_EQ(rs.face_submesh(g), 2u);
  expect_submeshes(rs);
  EXPECT_TRUE(m.validate().empty());
}

TEST(RenderBuffersSubmesh, CompactKeepsTheSubmeshesAndTheirRoom) {
  SurfaceMesh m = grid_with_submeshes(8);
  RenderBuffers rs(m, RenderOptions{.interleaved = false});
  for (int i = 0; i < 10; ++i) {
    const Edge e(static_cast<Index>(5 * i + 3));
    if (can_collapse(m, SurfaceMesh::halfedge(e, 0))) collapse(m, SurfaceMesh::halfedge(e, 0));
  }
  rs.sync();
  rs.compact();
  expect_submeshes(rs, true);
  for (std::size_t i = 0; i + 1 < rs.submesh_count(); ++i) EXPECT_GT(rs.submesh(i).index_count, 0u);
  // The room is used: a split of a face in the first submesh leaves the next one where it was.
  const std::uint32_t next_start = rs.submesh(1).index_start;
  const Face f = *m.faces().begin();
  ASSERT_EQ(rs.face_submesh(f), 0u);
  split_face(m, f, centre(m, f));
  rs.sync();
  EXPECT_EQ(rs.submesh(1).index_start, next_start);
  expect_submeshes(rs);
}

TEST(RenderBuffersSubmesh, SubdivisionAndDecimationKeepTheSubmeshes) {
  SurfaceMesh m = grid_with_submeshes(6);
  RenderBuffers rs(m);
  subdivide(m, Subdivision::loop);
  rs.sync();
  ASSERT_EQ(rs.submesh_count(), 3u);
  expect_submeshes(rs);
  DecimateOptions o;
  o.target_faces = m.n_faces() / 3;
  decimate(m, o);
  rs.sync();
  expect_submeshes(rs);
}

TEST(RenderBuffersSubmesh, ASubmeshAboveTheLimitIsRefused) {
  SurfaceMesh m = grid_with_submeshes(2);
  auto s = m.get_face_property<std::int32_t>("f:submesh");
  const Face f = *m.faces().begin();
  s[f] = 1 << 20;
  EXPECT_THROW(RenderBuffers rs(m), InvalidInputError);
  // A sync that meets one refuses too, and the buffers work on once the id is fixed.
  s[f] = 0;
  RenderBuffers rs(m);
  s[f] = 1 << 20;
  m.changes().mark(f, ChangeEvent::faces_changed);
  EXPECT_THROW(rs.sync(), InvalidInputError);
  s[f] = 2;
  rs.sync();
  EXPECT_EQ(rs.face_submesh(f), 2u);
  expect_submeshes(rs);
}

}  // namespace
}  // namespace hedge
