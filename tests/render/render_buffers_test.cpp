#include "hedge/render/render_buffers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "edits/random_edits.h"
#include "hedge/core/operations.h"
#include "hedge/io/io.h"
#include "test_meshes.h"

namespace hedge {
namespace {

std::string data(const char* name) { return std::string(HEDGE_DATA_DIR) + "/" + name; }

// A GPU-side copy of the buffers that only ever receives what sync() reports.
struct Mirror {
  std::vector<float> vertices;
  std::vector<std::uint32_t> indices;

  void apply(const RenderBuffers& rs, const SyncResult& r) {
    const auto v = rs.vertices();
    const auto ix = rs.indices();
    const std::size_t stride = rs.layout().stride;
    if (r.full) {
      vertices.assign(v.begin(), v.end());
      indices.assign(ix.begin(), ix.end());
      return;
    }
    vertices.resize(v.size(), -12345.f);
    indices.resize(ix.size(), 0xdeadbeefu);
    for (const SlotRange& s : r.vertex_ranges)
      std::copy_n(v.begin() + s.first * stride, s.count * stride, vertices.begin() + s.first * stride);
    for (const SlotRange& s : r.index_ranges)
      std::copy_n(ix.begin() + s.first, s.count, indices.begin() + s.first);
  }
  // Only vertices that some triangle uses must match: a freed slot may hold stale data.
  void expect_equal(const RenderBuffers& rs) const {
    const auto ix = rs.indices();
    ASSERT_EQ(indices.size(), ix.size());
    EXPECT_TRUE(std::equal(ix.begin(), ix.end(), indices.begin()));
    const auto v = rs.vertices();
    ASSERT_EQ(vertices.size(), v.size());
    const std::size_t stride = rs.layout().stride;
    for (std::size_t i = 0; i < rs.vertex_slots(); ++i) {
      if (!rs.render_vertex_source()[i].is_valid()) continue;
      for (std::size_t k = 0; k < stride; ++k)
        ASSERT_EQ(vertices[i * stride + k], v[i * stride + k]) << "render vertex " << i << " float " << k;
    }
  }
};

// Every live triangle as its vertices' floats, rotated to start at the smallest vertex (orientation
// kept), sorted: equal for two RenderBuffers that draw the same surface with the same attributes.
std::vector<std::vector<float>> triangle_set(const RenderBuffers& rs) {
  const auto v = rs.vertices();
  const auto ix = rs.indices();
  const std::size_t stride = rs.layout().stride;
  std::vector<std::vector<float>> out;
  for (std::size_t t = 0; t + 2 < ix.size(); t += 3) {
    if (ix[t] == ix[t + 1] && ix[t] == ix[t + 2]) continue;  // a free slot
    std::vector<float> c[3];
    for (int k = 0; k < 3; ++k)
      c[k].assign(v.begin() + ix[t + k] * stride, v.begin() + (ix[t + k] + 1) * stride);
    int first = 0;
    for (int k = 1; k < 3; ++k)
      if (c[k] < c[first]) first = k;
    std::vector<float> tri;
    for (int k = 0; k < 3; ++k) tri.insert(tri.end(), c[(first + k) % 3].begin(), c[(first + k) % 3].end());
    out.push_back(std::move(tri));
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The bookkeeping agrees with the mesh: every live face owns valence - 2 triangles over render
// vertices of its own corners, and every live render vertex is used.
void expect_consistent(const RenderBuffers& rs) {
  const SurfaceMesh& m = rs.mesh();
  const auto ix = rs.indices();
  const auto src = rs.render_vertex_source();
  const std::size_t stride = rs.layout().stride;
  std::vector<int> used(rs.vertex_slots(), 0);
  std::vector<int> slot_owner(ix.size() / 3, 0);
  std::size_t live_tris = 0;
  for (Face f : m.faces()) {
    const SlotRange r = rs.triangles(f);
    ASSERT_EQ(r.count, m.valence(f) - 2) << "face " << f.idx();
    live_tris += r.count;
    for (std::uint32_t t = r.first; t < r.first + r.count; ++t) {
      ASSERT_LT(t, slot_owner.size());
      EXPECT_EQ(slot_owner[t]++, 0) << "triangle slot " << t << " owned twice";
      EXPECT_EQ(rs.triangle_face(t), f) << "triangle slot " << t;
      for (int k = 0; k < 3; ++k) {
        const Index rv = ix[3 * t + k];
        ASSERT_LT(rv, rs.vertex_slots());
        ASSERT_TRUE(src[rv].is_valid());
        bool corner_of_f = false;
        for (Vertex w : m.vertices(f)) corner_of_f |= w == src[rv];
        EXPECT_TRUE(corner_of_f);
        ++used[rv];
      }
    }
    for (Halfedge h : m.halfedges(f)) {
      const Index rv = rs.render_vertex(h);
      ASSERT_LT(rv, rs.vertex_slots());
      EXPECT_EQ(src[rv], m.to_vertex(h));
      const Vec3 p = m.position(m.to_vertex(h));
      const float sx = rs.options().flip_x ? -1.f : 1.f;
      EXPECT_EQ(rs.vertices()[rv * stride + 0], sx * p.x);
      EXPECT_EQ(rs.vertices()[rv * stride + 1], p.y);
      EXPECT_EQ(rs.vertices()[rv * stride + 2], p.z);
    }
  }
  EXPECT_EQ(live_tris, rs.n_triangles());
  EXPECT_EQ(live_tris + rs.free_triangle_slots(), ix.size() / 3);
  std::size_t live_rv = 0;
  for (std::size_t i = 0; i < src.size(); ++i) {
    if (!src[i].is_valid()) continue;
    ++live_rv;
    EXPECT_GT(used[i], 0) << "render vertex " << i << " is live but unused";
    EXPECT_FALSE(m.is_deleted(src[i]));
  }
  EXPECT_EQ(live_rv, rs.n_vertices());
  for (std::size_t t = 0; t < slot_owner.size(); ++t)
    if (!slot_owner[t]) {
      EXPECT_TRUE(ix[3 * t] == ix[3 * t + 1] && ix[3 * t] == ix[3 * t + 2]) << "free slot " << t;
      EXPECT_FALSE(rs.triangle_face(t).is_valid()) << "free slot " << t;
    }
  EXPECT_EQ(rs.triangle_faces().size(), rs.triangle_slots());
  EXPECT_FALSE(rs.triangle_face(rs.triangle_slots()).is_valid());
  EXPECT_LE(rs.vertex_slots(), rs.vertex_capacity());
  EXPECT_LE(rs.index_count(), rs.index_capacity());
}

std::string floats_str(const std::vector<float>& v) {
  std::string s;
  for (float f : v) s += std::to_string(f) + " ";
  return s;
}

void expect_matches_fresh(const RenderBuffers& rs) {
  RenderBuffers fresh(rs.mesh(), rs.options());
  EXPECT_EQ(fresh.layout().stride, rs.layout().stride);
  const auto a = triangle_set(rs), b = triangle_set(fresh);
  EXPECT_EQ(a.size(), b.size());
  // Report the first difference only: the sets are large.
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    if (a[i] != b[i]) {
      ADD_FAILURE() << "triangle " << i << " differs from a fresh export:\n  synced " << floats_str(a[i])
                    << "\n  fresh  " << floats_str(b[i]);
      break;
    }
}

// What every sync must leave: the consumer's mirror equal to the buffers, the buffers consistent
// with themselves and with a fresh RenderBuffers of the same mesh.
void expect_in_sync(const Mirror& mirror, const RenderBuffers& rs) {
  mirror.expect_equal(rs);
  expect_consistent(rs);
  expect_matches_fresh(rs);
}

// A face whose removal is legal and whose corners are all interior.
Face removable_face(const SurfaceMesh& m) {
  for (Face f : m.faces()) {
    bool interior = true;
    for (Vertex v : m.vertices(f)) interior &= !m.is_boundary(v);
    if (interior && can_remove_face(m, f)) return f;
  }
  return {};
}

SurfaceMesh with_uv_seams(int n = 4) {
  // A grid whose texcoords jump along the column x = 2: a UV seam through n + 1 vertices.
  SurfaceMesh m = build(test::grid(n, true));
  auto uv = m.add_halfedge_property<Vec2>("h:texcoord");
  for (Face f : m.faces()) {
    float cx = 0;
    for (Vertex v : m.vertices(f)) cx += m.position(v).x / 3;
    for (Halfedge h : m.halfedges(f)) {
      const Vec3 p = m.position(m.to_vertex(h));
      uv[h] = Vec2{p.x + (cx > 2 ? 10.f : 0.f), p.y};
    }
  }
  return m;
}

TEST(RenderBuffers, FirstSyncMatchesTheMesh) {
  SurfaceMesh m = build(test::grid(4, false));  // quads
  RenderBuffers rs(m);
  EXPECT_EQ(rs.layout().stride, 6u);  // position + computed normal
  EXPECT_EQ(rs.layout().normal, 3);
  EXPECT_EQ(rs.layout().texcoord, -1);
  EXPECT_EQ(rs.vertex_slots(), m.n_vertices());
  EXPECT_EQ(rs.index_count(), 16u * 2 * 3);
  EXPECT_EQ(rs.seam_splits(), 0u);
  EXPECT_TRUE(rs.last_result().full);
  expect_consistent(rs);
  // The grid lies in z = 0 with CCW faces: every normal is +z.
  for (std::size_t i = 0; i < rs.vertex_slots(); ++i) EXPECT_FLOAT_EQ(rs.vertices()[i * 6 + 5], 1.f);
  // Nothing changed: nothing to upload.
  EXPECT_TRUE(rs.sync().empty());
}

TEST(RenderBuffers, SeamsSplitRenderVertices) {
  SurfaceMesh m = with_uv_seams();
  RenderBuffers rs(m);
  EXPECT_EQ(rs.layout().texcoord, 6);
  EXPECT_EQ(rs.layout().stride, 8u);
  // The 5 vertices of the seam column get a second render vertex each.
  EXPECT_EQ(rs.seam_splits(), 5u);
  EXPECT_EQ(rs.vertex_slots(), m.n_vertices() + 5);
  expect_consistent(rs);
}

TEST(RenderBuffers, FlipRewritesOnlyItsTwoTriangles) {
  SurfaceMesh m = build(test::grid(6, true));
  RenderBuffers rs(m, RenderOptions{.normals = NormalSource::none});
  Mirror mirror;
  mirror.apply(rs, rs.last_result());
  const Edge e = test::first_edge(m, [&](Edge c) { return can_flip(m, c); });
  ASSERT_TRUE(e.is_valid());
  const SlotRange a = rs.triangles(m.face(e, 0)), b = rs.triangles(m.face(e, 1));
  ASSERT_TRUE(flip(m, e).is_valid());
  const SyncResult& r = rs.sync();
  EXPECT_FALSE(r.full);
  EXPECT_FALSE(r.resized);
  EXPECT_TRUE(r.vertex_ranges.empty());  // no vertex changed
  std::size_t n = 0;
  for (const SlotRange& s : r.index_ranges) {
    n += s.count;
    EXPECT_TRUE(s.first == 3 * a.first || s.first == 3 * b.first ||
                s.first == 3 * std::min(a.first, b.first));
  }
  EXPECT_EQ(n, 6u);
  EXPECT_EQ(r.index_bytes, 24u);
  EXPECT_EQ(rs.triangles(m.face(e, 0)).count, 1u);
  mirror.apply(rs, r);
  expect_in_sync(mirror, rs);
  EXPECT_TRUE(m.validate().empty());
}

TEST(RenderBuffers, MovedVertexRewritesItsRenderVerticesAndNeighbourNormals) {
  SurfaceMesh m = with_uv_seams();
  RenderBuffers rs(m);  // computed normals
  Mirror mirror;
  mirror.apply(rs, rs.last_result());
  // A seam vertex inside the grid: two render vertices; lifting it tilts its neighbours' normals.
  Vertex v;
  for (Vertex w : m.vertices())
    if (!m.is_boundary(w) && m.position(w).x == 2.f) v = w;
  ASSERT_TRUE(v.is_valid());
  m.set_position(v, m.position(v) + Vec3{0, 0, 0.5f});
  const SyncResult& r = rs.sync();
  EXPECT_TRUE(r.index_ranges.empty());
  // v's two render vertices, and at most its neighbours' (two of them on the seam).
  EXPECT_GE(r.vertices_synced, 2u);
  EXPECT_LE(r.vertices_synced, 2u + m.valence(v) + 2u);
  for (Halfedge h : m.halfedges(v)) {
    const Index rv = rs.render_vertex(SurfaceMesh::twin(h));  // the corner at v
    bool written = false;
    for (const SlotRange& s : r.vertex_ranges) written |= rv >= s.first && rv < s.first + s.count;
    EXPECT_TRUE(written) << "render vertex " << rv;
  }
  mirror.apply(rs, r);
  expect_in_sync(mirror, rs);
  EXPECT_TRUE(m.validate().empty());
}

// Random edits of every kind, with a sync after each: the mirror that received only the dirty
// ranges must equal the buffers, and the buffers must draw what a fresh export draws.
void random_edit_run(SurfaceMesh m, const RenderOptions& options, std::size_t steps) {
  RenderBuffers rs(m, options);
  Mirror mirror;
  mirror.apply(rs, rs.last_result());
  std::mt19937 rng(7);
  RandomEditor editor(m, 1000);
  for (std::size_t step = 0; step < steps; ++step) {
    if (step % 3 == 0) {
      std::vector<Vertex> live;
      for (Vertex v : m.vertices()) live.push_back(v);
      const Vertex v = live[rng() % live.size()];
      m.set_position(v, m.position(v) + Vec3{0.01f, -0.02f, 0.03f});
    } else {
      editor.step();
    }
    mirror.apply(rs, rs.sync());
    if (step % 25 == 0 || step + 1 == steps) {
      SCOPED_TRACE("step " + std::to_string(step));
      expect_in_sync(mirror, rs);
    }
  }
  EXPECT_TRUE(m.validate().empty());
}

TEST(RenderBuffers, RandomEditsOnATexturedTriangleMesh) {
  random_edit_run(read_mesh(data("spot_triangulated.obj")), {}, 400);
}

TEST(RenderBuffers, RandomEditsOnAQuadMeshWithSeparateStreamsAndClockwiseWinding) {
  SurfaceMesh m = read_mesh(data("spot_control_mesh.obj"));
  RenderOptions o;
  o.winding = Winding::cw;
  o.flip_x = true;
  random_edit_run(std::move(m), o, 300);
}

TEST(RenderBuffers, RandomEditsOnAnOpenMeshWithComputedNormals) {
  random_edit_run(read_mesh(data("elephant-with-holes.off")), {}, 300);
}

// ---- Normals that follow the geometry --------------------------------------------------------------

// A flat grid with imported corner normals that are not its geometric ones: (0.6, 0, 0.8) left of
// x = 2 and (0, 0.6, 0.8) right of it, so the column x = 2 is a crease (two render vertices per
// vertex there).
SurfaceMesh with_imported_normals() {
  SurfaceMesh m = build(test::grid(4, true));
  auto n = m.add_halfedge_property<Vec3>("h:normal");
  for (Face f : m.faces()) {
    const bool right = face_centroid(m, f).x > 2;
    for (Halfedge h : m.halfedges(f)) n[h] = right ? Vec3{0, 0.6f, 0.8f} : Vec3{0.6f, 0, 0.8f};
  }
  return m;
}

// The area-weighted normal of the faces about v accepted by `side` (all faces: any side).
Vec3 expected_normal(const SurfaceMesh& m, Vertex v, int side = 0) {
  Vec3d sum{0, 0, 0};
  for (Face f : m.faces(v)) {
    const double cx = face_centroid(m, f).x;
    if ((side < 0 && cx > 2) || (side > 0 && cx < 2)) continue;
    std::vector<Vec3d> p;
    for (Vertex w : m.vertices(f)) p.push_back(to_double(m.position(w)));
    sum += cross(p[1] - p[0], p[2] - p[0]);
  }
  return to_float(normalize(sum));
}

Vec3 render_normal(const RenderBuffers& rs, Halfedge corner) {
  const Index rv = rs.render_vertex(corner);
  const float* n = rs.vertices().data() + std::size_t(rv) * rs.layout().stride + rs.layout().normal;
  return {n[0], n[1], n[2]};
}

void expect_near(const Vec3& a, const Vec3& b, const char* what) {
  EXPECT_NEAR(a.x, b.x, 1e-6f) << what;
  EXPECT_NEAR(a.y, b.y, 1e-6f) << what;
  EXPECT_NEAR(a.z, b.z, 1e-6f) << what;
}

TEST(RenderBuffers, ImportedNormalsFollowAMovedVertexByDefault) {
  SurfaceMesh m = with_imported_normals();
  RenderBuffers rs(m);  // automatic
  Mirror mirror;
  mirror.apply(rs, rs.last_result());
  const Vertex v(6), far(19);  // (1, 1) inside the left half; (4, 3) on the far right edge
  const Halfedge far_corner = SurfaceMesh::twin(m.halfedge(far));
  ASSERT_TRUE(!m.is_boundary(far_corner));
  m.set_position(v, m.position(v) + Vec3{0, 0, 0.5f});
  mirror.apply(rs, rs.sync());
  // Area-weighted, the lifted vertex's normal is its flat link's: +z, no longer the imported one.
  const Vec3 want = expected_normal(m, v);
  expect_near(want, Vec3{0, 0, 1}, "the lifted vertex's normal");
  auto n = m.get_halfedge_property<Vec3>("h:normal");
  for (Halfedge o : m.halfedges(v)) {
    const Halfedge c = SurfaceMesh::twin(o);
    if (m.is_boundary(c)) continue;
    expect_near(render_normal(rs, c), want, "the moved vertex's render normal");
    expect_near(n[c], want, "written into the mesh's corner normals");
  }
  // A neighbour's normal tilts too; a vertex away from the edit keeps its imported normal.
  const Vertex neighbour(11);  // (1, 2)
  ASSERT_TRUE(m.find_halfedge(v, neighbour).is_valid());
  const Vec3 tilted = expected_normal(m, neighbour);
  EXPECT_GT(std::abs(tilted.x) + std::abs(tilted.y), 0.01f);
  for (Halfedge o : m.halfedges(neighbour))
    expect_near(render_normal(rs, SurfaceMesh::twin(o)), tilted, "the neighbour");
  EXPECT_EQ(render_normal(rs, far_corner), (Vec3{0, 0.6f, 0.8f}));
  expect_in_sync(mirror, rs);
  EXPECT_TRUE(m.validate().empty());
}

TEST(RenderBuffers, ACreaseStaysWhenItsVertexMoves) {
  SurfaceMesh m = with_imported_normals();
  RenderBuffers rs(m);
  const Vertex v(12);  // (2, 2), on the crease
  const std::size_t before = rs.n_vertices();
  m.set_position(v, m.position(v) + Vec3{0, 0, 0.5f});
  rs.sync();
  EXPECT_EQ(rs.n_vertices(), before);  // still two render vertices at v
  for (Halfedge o : m.halfedges(v)) {
    const Halfedge c = SurfaceMesh::twin(o);
    const int side = face_centroid(m, m.face(c)).x > 2 ? 1 : -1;
    expect_near(render_normal(rs, c), expected_normal(m, v, side), "each side from its own faces");
  }
  expect_consistent(rs);
  EXPECT_TRUE(m.validate().empty());
}

TEST(RenderBuffers, KeptImportedNormalsDoNotFollow) {
  SurfaceMesh m = with_imported_normals();
  RenderBuffers rs(m, RenderOptions{.normals = NormalSource::attribute});
  const Vertex v(6);
  m.set_position(v, m.position(v) + Vec3{0, 0, 0.5f});
  const SyncResult& r = rs.sync();
  EXPECT_GT(r.vertices_synced, 0u);  // the position moved
  for (Halfedge o : m.halfedges(v)) EXPECT_EQ(render_normal(rs, SurfaceMesh::twin(o)), (Vec3{0.6f, 0, 0.8f}));
  EXPECT_EQ(m.get_halfedge_property<Vec3>("h:normal")[SurfaceMesh::twin(m.halfedge(v))],
            (Vec3{0.6f, 0, 0.8f}));
  expect_consistent(rs);
  EXPECT_TRUE(m.validate().empty());
}

TEST(RenderBuffers, RandomEditsWithImportedNormalsFollowing) {
  random_edit_run(with_imported_normals(), {}, 300);
}

TEST(RenderBuffers, TransactionSyncsOnceAtCommit) {
  SurfaceMesh m = build(test::grid(8, true));
  RenderBuffers rs(m);
  Mirror mirror;
  mirror.apply(rs, rs.last_result());
  rs.begin();
  std::size_t edits = 0;
  std::vector<Edge> all;
  for (Edge e : m.edges()) all.push_back(e);
  std::vector<Face> touched;
  for (Edge e : all) {
    if (edits == 20) break;
    if (can_flip(m, e) && flip(m, e).is_valid()) {
      ++edits;
      touched.push_back(m.face(e, 0));
      touched.push_back(m.face(e, 1));
    }
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  EXPECT_TRUE(rs.in_transaction());
  EXPECT_TRUE(rs.sync().empty());  // deferred
  const SyncResult& r = rs.commit();
  EXPECT_FALSE(rs.in_transaction());
  EXPECT_FALSE(r.empty());
  EXPECT_EQ(r.faces_synced, touched.size());
  for (std::size_t i = 1; i < r.index_ranges.size(); ++i)
    EXPECT_GT(r.index_ranges[i].first, r.index_ranges[i - 1].first + r.index_ranges[i - 1].count);
  mirror.apply(rs, r);
  mirror.expect_equal(rs);
  expect_matches_fresh(rs);
  EXPECT_TRUE(m.validate().empty());
}

TEST(RenderBuffers, RemovedFacesFreeSlotsThatNewFacesReuse) {
  SurfaceMesh m = build(test::grid(4, true));
  RenderBuffers rs(m, RenderOptions{.normals = NormalSource::none});
  const std::size_t slots = rs.index_count();
  const Face f = removable_face(m);
  ASSERT_TRUE(f.is_valid());
  std::vector<Vertex> corners;
  for (Vertex v : m.vertices(f)) corners.push_back(v);
  const SlotRange was = rs.triangles(f);
  ASSERT_TRUE(remove_face(m, f));
  rs.sync();
  EXPECT_EQ(rs.free_triangle_slots(), 1u);
  EXPECT_EQ(rs.indices()[3 * was.first], rs.indices()[3 * was.first + 1]);  // degenerate now
  expect_consistent(rs);
  const Face g = add_face(m, corners);
  ASSERT_TRUE(g.is_valid());
  const SyncResult& r = rs.sync();
  EXPECT_EQ(rs.triangles(g).first, was.first);  // the freed slot is reused
  EXPECT_EQ(rs.index_count(), slots);
  EXPECT_FALSE(r.resized);
  EXPECT_EQ(rs.free_triangle_slots(), 0u);
  expect_consistent(rs);
  expect_matches_fresh(rs);
  EXPECT_TRUE(m.validate().empty());
}

TEST(RenderBuffers, CompactRemovesHolesAndReportsTheMaps) {
  SurfaceMesh m = with_uv_seams(8);
  RenderBuffers rs(m);
  for (int i = 0; i < 3; ++i) {
    const Face f = removable_face(m);
    ASSERT_TRUE(f.is_valid());
    ASSERT_TRUE(remove_face(m, f));
  }
  rs.sync();
  ASSERT_GT(rs.free_triangle_slots(), 0u);
  const std::vector<std::uint32_t> old_indices(rs.indices().begin(), rs.indices().end());
  const std::size_t stride = rs.layout().stride;
  const std::vector<float> old_vertices(rs.vertices().begin(), rs.vertices().end());
  const RenderRemap map = rs.compact();
  EXPECT_EQ(rs.free_triangle_slots(), 0u);
  EXPECT_EQ(rs.index_count(), 3 * rs.n_triangles());
  EXPECT_EQ(rs.vertex_slots(), rs.n_vertices());
  ASSERT_EQ(map.triangles.size(), old_indices.size() / 3);
  for (std::size_t t = 0; t < map.triangles.size(); ++t) {
    if (map.triangles[t] == kInvalidIndex) continue;
    for (int k = 0; k < 3; ++k) {
      const Index o = old_indices[3 * t + k];
      EXPECT_EQ(rs.indices()[3 * map.triangles[t] + k], map.vertices[o]);
      for (std::size_t c = 0; c < stride; ++c)
        EXPECT_EQ(rs.vertices()[map.vertices[o] * stride + c], old_vertices[o * stride + c]);
    }
  }
  expect_consistent(rs);
  expect_matches_fresh(rs);
  EXPECT_TRUE(rs.last_result().full);
  // Edits go on after compaction. The first sync after it reports whole buffers, so that a
  // consumer following only sync results (the Unity component) uploads what compaction moved.
  Edge e;
  for (Edge c : m.edges())
    if (can_flip(m, c)) e = c;
  ASSERT_TRUE(flip(m, e).is_valid());
  const SyncResult& after = rs.sync();
  EXPECT_TRUE(after.full && after.resized);
  ASSERT_EQ(after.index_ranges.size(), 1u);
  EXPECT_EQ(after.index_ranges[0].count, rs.index_count());
  EXPECT_EQ(after.faces_synced, 2u);  // the flip's two faces were synced as well
  EXPECT_FALSE(rs.sync().full);       // once
  rs.compact();
  EXPECT_TRUE(rs.sync().full);  // also with nothing edited in between
  expect_consistent(rs);
  expect_matches_fresh(rs);
  EXPECT_TRUE(m.validate().empty());
}

// An engine's ray hit names a triangle of the uploaded index buffer; triangle_face() must name the
// face whose triangle that is after splits, collapses and compaction, as the buffers do.
TEST(RenderBuffers, TriangleFaceFollowsSplitCollapseAndCompact) {
  SurfaceMesh m = with_uv_seams(6);
  RenderBuffers rs(m);
  // The triangle a hit reports, found the way an engine would: by its corners in the index buffer.
  auto triangle_of_corners = [&](Face f) {
    std::vector<Vertex> want;
    for (Vertex v : m.vertices(f)) want.push_back(v);
    std::sort(want.begin(), want.end());
    for (std::size_t t = 0; t < rs.triangle_slots(); ++t) {
      std::vector<Vertex> got;
      for (int k = 0; k < 3; ++k) got.push_back(rs.render_vertex_source()[rs.indices()[3 * t + k]]);
      std::sort(got.begin(), got.end());
      if (got == want) return t;
    }
    return std::size_t(-1);
  };
  Edge e = *m.edges().begin();
  const Vec3 mid =
      0.5f * (m.position(m.from_vertex(m.halfedge(e, 0))) + m.position(m.to_vertex(m.halfedge(e, 0))));
  const Vertex v = split_edge(m, e, mid);
  ASSERT_TRUE(v.is_valid());
  rs.sync();
  for (Face f : m.faces(v)) {
    const std::size_t t = triangle_of_corners(f);
    ASSERT_NE(t, std::size_t(-1));
    EXPECT_EQ(rs.triangle_face(t), f);
  }
  expect_consistent(rs);
  // Collapse the new vertex away again: the slots of the faces it deletes are freed and name no face.
  std::vector<std::pair<Face, std::size_t>> before;
  for (Face f : m.faces(v)) before.push_back({f, rs.triangles(f).first});
  Halfedge h;
  for (Halfedge c : m.halfedges(v))
    if (can_collapse(m, c)) h = c;
  ASSERT_TRUE(h.is_valid());
  const Vertex survivor = collapse(m, h);
  ASSERT_TRUE(survivor.is_valid());
  rs.sync();
  std::size_t deleted = 0;
  for (const auto& [f, t] : before) {
    if (!m.is_deleted(f)) continue;
    ++deleted;
    EXPECT_FALSE(rs.triangle_face(t).is_valid()) << "the freed slot " << t << " of a deleted face";
  }
  EXPECT_GE(deleted, 1u);  // one face on a boundary edge, two inside
  for (Face f : m.faces(survivor)) EXPECT_EQ(rs.triangle_face(rs.triangles(f).first), f);
  expect_consistent(rs);
  // Compaction moves every triangle: the map moves with it.
  ASSERT_GT(rs.free_triangle_slots(), 0u);
  rs.compact();
  EXPECT_EQ(rs.triangle_faces().size(), rs.n_triangles());
  for (Face f : m.faces()) {
    const std::size_t t = triangle_of_corners(f);
    ASSERT_NE(t, std::size_t(-1));
    EXPECT_EQ(rs.triangle_face(t), f);
  }
  expect_consistent(rs);
  EXPECT_TRUE(m.validate().empty());
}

TEST(RenderBuffers, GarbageCollectionRebuilds) {
  SurfaceMesh m = build(test::grid(4, true));
  RenderBuffers rs(m);
  ASSERT_TRUE(remove_face(m, removable_face(m)));
  m.garbage_collection();
  const SyncResult& r = rs.sync();
  EXPECT_TRUE(r.full);
  EXPECT_EQ(rs.free_triangle_slots(), 0u);
  expect_consistent(rs);
  EXPECT_TRUE(m.validate().empty());
}

TEST(RenderBuffers, FlipXNegatesTheNormalsToo) {
  // A tetrahedron: unlike a flat grid's, some of its normals leave the x = 0 plane, so a missing
  // negation shows.
  SurfaceMesh m = build(test::tetrahedron());
  const RenderBuffers plain(m, RenderOptions{.normals = NormalSource::computed});
  const RenderBuffers flipped(m, RenderOptions{.normals = NormalSource::computed, .flip_x = true});
  std::size_t off_plane = 0;
  for (Halfedge h : m.halfedges()) {
    if (m.is_boundary(h)) continue;
    const Vec3 a = render_normal(plain, h), b = render_normal(flipped, h);
    off_plane += std::abs(a.x) > 1e-3f;
    EXPECT_EQ(b.x, -a.x);
    EXPECT_EQ(b.y, a.y);
    EXPECT_EQ(b.z, a.z);
  }
  EXPECT_GT(off_plane, 0u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(RenderBuffers, WindingAndAxes) {
  SurfaceMesh m = build(test::grid(2, true));
  RenderBuffers ccw(m, RenderOptions{.normals = NormalSource::computed});
  RenderBuffers cw(m,
                   RenderOptions{.normals = NormalSource::computed, .winding = Winding::cw, .flip_x = true});
  for (Face f : m.faces()) {
    const SlotRange a = ccw.triangles(f), b = cw.triangles(f);
    const auto i = ccw.indices().subspan(3 * a.first, 3), j = cw.indices().subspan(3 * b.first, 3);
    // Same corners, reversed order.
    const Index s0 = ccw.render_vertex_source()[i[0]].idx(), s1 = ccw.render_vertex_source()[i[1]].idx(),
                s2 = ccw.render_vertex_source()[i[2]].idx();
    EXPECT_EQ(cw.render_vertex_source()[j[0]].idx(), s0);
    EXPECT_EQ(cw.render_vertex_source()[j[1]].idx(), s2);
    EXPECT_EQ(cw.render_vertex_source()[j[2]].idx(), s1);
  }
  for (std::size_t k = 0; k < ccw.vertex_slots(); ++k) {
    const Vertex v = ccw.render_vertex_source()[k];
    EXPECT_EQ(ccw.vertices()[k * 6 + 0], m.position(v).x);
  }
  for (std::size_t k = 0; k < cw.vertex_slots(); ++k) {
    const Vertex v = cw.render_vertex_source()[k];
    EXPECT_EQ(cw.vertices()[k * 6 + 0], -m.position(v).x);
  }
}

TEST(RenderBuffers, SeparateStreamsHoldTheInterleavedData) {
  SurfaceMesh m = with_uv_seams();
  auto color = m.add_vertex_property<Color>("v:color");
  for (Vertex v : m.vertices()) color[v] = Color{m.position(v).x / 4, 0.5f, 0.25f, 1};
  RenderBuffers a(m);
  RenderBuffers b(m, RenderOptions{.interleaved = false});
  EXPECT_EQ(a.layout().stride, 12u);
  EXPECT_EQ(a.layout().color, 8);
  EXPECT_FALSE(b.layout().interleaved);
  ASSERT_EQ(a.vertex_slots(), b.vertex_slots());
  EXPECT_TRUE(a.normals().empty());
  for (std::size_t k = 0; k < a.vertex_slots(); ++k) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(a.vertices()[k * 12 + c], b.positions()[k * 3 + c]);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(a.vertices()[k * 12 + 3 + c], b.normals()[k * 3 + c]);
    for (int c = 0; c < 2; ++c) EXPECT_EQ(a.vertices()[k * 12 + 6 + c], b.texcoords()[k * 2 + c]);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(a.vertices()[k * 12 + 8 + c], b.colors()[k * 4 + c]);
  }
  EXPECT_TRUE(std::equal(a.indices().begin(), a.indices().end(), b.indices().begin()));
  // A colour change marked on the vertex reaches the colour stream only.
  color[Vertex(0)] = Color{1, 0, 0, 1};
  m.mark_changed(Vertex(0), ChangeEvent::vertex_data_changed);
  const SyncResult& r = b.sync();
  ASSERT_EQ(r.vertex_ranges.size(), 1u);
  EXPECT_EQ(b.colors()[r.vertex_ranges[0].first * 4], 1.f);
  EXPECT_EQ(r.vertex_bytes, 12u * sizeof(float));
  EXPECT_TRUE(m.validate().empty());
}

TEST(RenderBuffers, GrowthWithinCapacityIsNotAResize) {
  SurfaceMesh m = build(test::grid(10, true));
  RenderBuffers rs(m);
  std::size_t resizes = 0, syncs = 0;
  for (int i = 0; i < 200; ++i) {
    std::vector<Edge> es;
    for (Edge c : m.edges()) es.push_back(c);
    const Edge e = es[(i * 7919u) % es.size()];
    split_edge(m, e, 0.5f * (m.position(m.vertex(e, 0)) + m.position(m.vertex(e, 1))));
    resizes += rs.sync().resized;
    ++syncs;
  }
  EXPECT_LT(resizes, 12u);  // geometric growth: a handful of reallocations for 200 splits
  expect_consistent(rs);
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge

namespace hedge {
namespace {

TEST(RenderBuffers, TwoConsumersOfOneMeshSyncAtTheirOwnPace) {
  SurfaceMesh m = with_uv_seams(6);
  RenderBuffers a(m), b(m, RenderOptions{.winding = Winding::cw});
  Mirror ma, mb;
  ma.apply(a, a.last_result());
  mb.apply(b, b.last_result());
  std::vector<Edge> edges;
  for (Edge e : m.edges()) edges.push_back(e);
  int flips = 0;
  for (Edge e : edges) {
    if (!can_flip(m, e)) continue;
    flip(m, e);
    ma.apply(a, a.sync());  // a after every edit, b after every third
    if (++flips % 3 == 0) mb.apply(b, b.sync());
  }
  mb.apply(b, b.sync());
  ma.expect_equal(a);
  mb.expect_equal(b);
  expect_matches_fresh(a);
  expect_matches_fresh(b);
  EXPECT_TRUE(m.validate().empty());
}

// The change log counts each RenderBuffers' transactions for its consumer: one RenderBuffers'
// transaction defers neither another's syncs nor those of code that opens its own on the log, and
// only the log's subscribers wait for every transaction to close.
TEST(RenderBuffers, ATransactionBelongsToTheRenderBuffersThatOpenedIt) {
  SurfaceMesh m = with_uv_seams(6);
  ChangeLog& log = m.changes();
  int heard = 0;
  log.subscribe(ChangeEvent::all, [&](ChangeEvent) { ++heard; });
  auto flip_one = [&] {
    for (Edge e : m.edges())
      if (can_flip(m, e)) return flip(m, e).is_valid();
    return false;
  };
  RenderBuffers a(m), b(m);
  Mirror ma, mb;
  ma.apply(a, a.last_result());
  mb.apply(b, b.last_result());

  a.begin();
  a.begin();
  EXPECT_TRUE(a.in_transaction());
  EXPECT_FALSE(b.in_transaction());
  EXPECT_TRUE(log.in_transaction());
  ASSERT_TRUE(flip_one());
  EXPECT_TRUE(a.sync().empty());
  const SyncResult& rb = b.sync();  // b syncs inside a's transaction
  EXPECT_FALSE(rb.empty());
  mb.apply(b, rb);
  EXPECT_TRUE(b.commit().empty());  // b has none open, and a's stays open
  EXPECT_TRUE(a.in_transaction());
  EXPECT_EQ(heard, 0);
  EXPECT_TRUE(a.commit().empty());  // inner
  EXPECT_EQ(heard, 0);
  const SyncResult& ra = a.commit();
  EXPECT_FALSE(ra.empty());
  ma.apply(a, ra);
  EXPECT_FALSE(a.in_transaction());
  EXPECT_FALSE(log.in_transaction());
  EXPECT_EQ(heard, 1);

  // A transaction opened on the log itself is nobody's: a syncs, and a's commit does not close it.
  log.begin();
  EXPECT_FALSE(a.in_transaction());
  ASSERT_TRUE(flip_one());
  const SyncResult& r = a.sync();
  EXPECT_FALSE(r.empty());
  ma.apply(a, r);
  EXPECT_TRUE(a.commit().empty());
  EXPECT_TRUE(log.in_transaction());
  EXPECT_EQ(heard, 1);
  EXPECT_TRUE(log.commit());
  EXPECT_EQ(heard, 2);

  // A RenderBuffers destroyed inside its transactions closes them.
  {
    RenderBuffers c(m);
    c.begin();
    c.begin();
    ASSERT_TRUE(flip_one());
    EXPECT_EQ(heard, 2);
  }
  EXPECT_FALSE(log.in_transaction());
  EXPECT_EQ(heard, 3);

  mb.apply(b, b.sync());
  ma.apply(a, a.sync());
  ma.expect_equal(a);
  mb.expect_equal(b);
  expect_matches_fresh(a);
  expect_matches_fresh(b);
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge

// Deprecated names (kept for one release): RenderSync still names RenderBuffers.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
static_assert(std::is_same_v<hedge::RenderSync, hedge::RenderBuffers>);
#pragma GCC diagnostic pop
// End of deprecated names
