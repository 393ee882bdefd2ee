#include "hedge/render/engine_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

#include "hedge/algorithms/normals.h"
#include "hedge/core/edge_operations.h"
#include "hedge/core/face_operations.h"
#include "hedge/core/operations.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "hedge/render/render_buffers.h"

namespace hedge {
namespace {

// An engine mesh: one vertex per distinct (position, texcoord, normal) corner of an OBJ file, as
// an engine importer makes it; seams become duplicated vertices.
struct EngineMesh {
  std::vector<Vec3> positions, normals;
  std::vector<Vec2> texcoords;
  std::vector<Color> colors;
  std::vector<std::uint32_t> indices;
  EngineMeshView view() const { return {positions, indices, normals, texcoords, colors}; }
};

EngineMesh engine_mesh_from(const IndexedMesh& in) {
  EngineMesh e;
  std::map<std::tuple<Index, Index, Index>, Index> ids;
  for (std::size_t c = 0; c < in.indices.size(); ++c) {
    const Index p = in.indices[c];
    const Index t = in.texcoord_indices.empty() ? 0 : in.texcoord_indices[c];
    const Index n = in.normal_indices.empty() ? 0 : in.normal_indices[c];
    auto [it, fresh] = ids.try_emplace({p, t, n}, static_cast<Index>(e.positions.size()));
    if (fresh) {
      e.positions.push_back(in.positions[p]);
      if (!in.texcoords.empty()) e.texcoords.push_back(in.texcoords[t]);
      if (!in.normals.empty()) e.normals.push_back(in.normals[n]);
      // A colour per engine vertex, different on each side of a seam.
      e.colors.push_back(Color{float(p % 7) / 7, float(t % 5) / 5, 0.5f, 1});
    }
    e.indices.push_back(it->second);
  }
  return e;
}

// Each engine triangle must come back as the same three vertices: same floats, same order.
void expect_round_trip(const EngineMesh& e, const EngineImportOptions& io, const RenderOptions& ro) {
  BuildReport report;
  SurfaceMesh m = from_engine_mesh(e.view(), io, &report);
  EXPECT_TRUE(m.validate().empty());
  EXPECT_EQ(report.repairs(), 0u);
  RenderBuffers rs(m, ro);
  const VertexLayout& l = rs.layout();
  ASSERT_EQ(l.texcoord >= 0, !e.texcoords.empty());
  ASSERT_GE(l.color, 0);
  ASSERT_EQ(rs.n_triangles(), e.indices.size() / 3);
  std::size_t split_count = 0;
  for (std::size_t t = 0; t < e.indices.size() / 3; ++t) {
    const Face f(report.face_map[t]);
    const SlotRange r = rs.triangles(f);
    ASSERT_EQ(r.count, 1u);
    for (int k = 0; k < 3; ++k) {
      const Index ev = e.indices[3 * t + k];
      const Index rv = rs.indices()[3 * r.first + k];
      const float* got = rs.vertices().data() + rv * l.stride;
      EXPECT_EQ(got[0], e.positions[ev].x);
      EXPECT_EQ(got[1], e.positions[ev].y);
      EXPECT_EQ(got[2], e.positions[ev].z);
      if (l.normal >= 0 && !e.normals.empty()) {
        EXPECT_EQ(got[l.normal + 0], e.normals[ev].x);
        EXPECT_EQ(got[l.normal + 1], e.normals[ev].y);
        EXPECT_EQ(got[l.normal + 2], e.normals[ev].z);
      }
      if (l.texcoord >= 0) {
        EXPECT_EQ(got[l.texcoord + 0], e.texcoords[ev].x);
        EXPECT_EQ(got[l.texcoord + 1], e.texcoords[ev].y);
      }
      EXPECT_EQ(got[l.color + 0], e.colors[ev].r);
      EXPECT_EQ(got[l.color + 1], e.colors[ev].g);
    }
  }
  // Welding made the topology: fewer mesh vertices than engine vertices, and exactly as many
  // render vertices as the engine had (each engine vertex is one attribute set on one position).
  EXPECT_LT(m.n_vertices(), e.positions.size());
  EXPECT_EQ(rs.n_vertices(), e.positions.size());
  split_count = rs.seam_splits();
  EXPECT_EQ(split_count, e.positions.size() - m.n_vertices());
}

TEST(EngineMesh, SeamsSurviveARoundTripOnSpot) {
  const IndexedMesh obj = read_indexed_file(std::string(HEDGE_DATA_DIR) + "/spot_triangulated.obj");
  ASSERT_FALSE(obj.texcoord_indices.empty());
  const EngineMesh e = engine_mesh_from(obj);
  ASSERT_GT(e.positions.size(), obj.positions.size());  // the UV seams duplicated vertices
  expect_round_trip(e, {}, {});
}

TEST(EngineMesh, UnityDataNeedsNoConversion) {
  // The original project's quad, as a Unity Mesh holds it: Unity's front faces are clockwise in
  // its left-handed axes, which gives the same cross-product normal as counter-clockwise faces in
  // right-handed axes. So the default options (no winding change, no mirroring) keep the user's
  // own coordinates, compute the normals Unity's RecalculateNormals would (-z here), and give the
  // same triangles back in the same winding.
  EngineMesh e;
  e.positions = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}};
  e.indices = {0, 1, 2, 2, 1, 3};
  BuildReport report;
  SurfaceMesh m = from_engine_mesh(e.view(), {}, &report);
  ASSERT_EQ(m.n_vertices(), 4u);
  for (Index v = 0; v < 4; ++v) {
    const Vertex mv(report.vertex_map[v]);
    EXPECT_EQ(m.position(mv), e.positions[v]) << "vertex " << v << " kept bit for bit";
  }
  for (Face f : m.faces()) EXPECT_EQ(face_normal(m, f), (Vec3{0, 0, -1}));
  RenderBuffers rs(m, RenderOptions{.normals = NormalSource::computed});
  const VertexLayout& l = rs.layout();
  ASSERT_GE(l.normal, 0);
  ASSERT_EQ(rs.n_triangles(), 2u);
  for (std::size_t t = 0; t < 2; ++t) {
    const SlotRange r = rs.triangles(Face(report.face_map[t]));
    for (int k = 0; k < 3; ++k) {
      const float* got = rs.vertices().data() + rs.indices()[3 * r.first + k] * l.stride;
      const Vec3 want = e.positions[e.indices[3 * t + k]];
      EXPECT_EQ((Vec3{got[0], got[1], got[2]}), want) << "triangle " << t << " corner " << k;
      EXPECT_EQ((Vec3{got[l.normal], got[l.normal + 1], got[l.normal + 2]}), (Vec3{0, 0, -1}));
    }
  }
  // Moving a vertex moves it where the user said, in the user's axes.
  m.set_position(Vertex(report.vertex_map[2]), {1, 0.5f, 0});
  rs.sync();
  const SlotRange r = rs.triangles(Face(report.face_map[0]));
  const float* moved = rs.vertices().data() + rs.indices()[3 * r.first + 2] * l.stride;
  EXPECT_EQ((Vec3{moved[0], moved[1], moved[2]}), (Vec3{1, 0.5f, 0}));
  EXPECT_TRUE(m.validate().empty());
}

TEST(EngineMesh, MirroredConventionsRoundTrip) {
  // Data in the other handedness (a right-handed file mirrored into left-handed axes, winding
  // reversed): importing and exporting with winding and flip_x set gives the engine its own arrays
  // back; the half-edge mesh in between is the file's, so its normals point outwards.
  const IndexedMesh obj = read_indexed_file(std::string(HEDGE_DATA_DIR) + "/spot_triangulated.obj");
  EngineMesh e = engine_mesh_from(obj);
  for (Vec3& p : e.positions) p.x = -p.x;
  for (std::size_t t = 0; t < e.indices.size(); t += 3) std::swap(e.indices[t + 1], e.indices[t + 2]);
  EngineImportOptions io;
  io.winding = Winding::cw;
  io.flip_x = true;
  RenderOptions ro;
  ro.winding = Winding::cw;
  ro.flip_x = true;
  expect_round_trip(e, io, ro);
  SurfaceMesh m = from_engine_mesh(e.view(), io);
  // The internal mesh equals the OBJ's (right-handed, CCW): same signed volume sign.
  double vol = 0;
  for (Face f : m.faces()) {
    std::vector<Vec3d> p;
    for (Vertex v : m.vertices(f)) p.push_back(to_double(m.position(v)));
    vol += dot(p[0], cross(p[1], p[2])) / 6;
  }
  EXPECT_GT(vol, 0);
}

TEST(EngineMesh, BadInputIsRejectedWithAClearMessage) {
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<std::uint32_t> ok = {0, 1, 2}, bad = {0, 1, 3}, partial = {0, 1};
  std::vector<Vec2> short_uv = {{0, 0}};
  std::vector<Vec3> nan_n = {{0, 0, 1}, {0, 0, NAN}, {0, 0, 1}};
  auto message = [](const EngineMeshView& v) -> std::string {
    try {
      from_engine_mesh(v);
    } catch (const InvalidInputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message({p, bad}).find("index 2 (triangle 0) is 3"), std::string::npos) << message({p, bad});
  EXPECT_NE(message({p, partial}).find("whole number of triangles"), std::string::npos);
  EXPECT_NE(message({p, ok, {}, short_uv}).find("texcoords has 1 entries for 3 vertices"), std::string::npos);
  EXPECT_NE(message({p, ok, nan_n}).find("normal of vertex 1"), std::string::npos);
  std::vector<Vec3> nan_p = p;
  nan_p[2].y = NAN;
  EXPECT_THROW(from_engine_mesh({nan_p, ok}), InvalidInputError);
  SurfaceMesh m = from_engine_mesh({p, ok});
  EXPECT_EQ(m.n_faces(), 1u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(EngineMesh, SubmeshesBecomeAFacePropertyThatRenderBuffersGroupBy) {
  // A quad of two materials: triangle 0 in submesh 1, triangle 1 in submesh 0, plus a degenerate
  // triangle that the build drops (its submesh must not shift the others').
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  std::vector<std::uint32_t> ix = {0, 1, 2, 0, 0, 1, 0, 2, 3};
  std::vector<std::int32_t> sub = {1, 7, 0};
  EngineMeshView v{p, ix};
  v.submeshes = sub;
  SurfaceMesh m = from_engine_mesh(v);
  ASSERT_EQ(m.n_faces(), 2u);
  auto prop = m.get_face_property<std::int32_t>("f:submesh");
  ASSERT_TRUE(prop);
  for (Face f : m.faces()) {
    bool has_v1 = false;
    for (Vertex w : m.vertices(f)) has_v1 |= m.position(w) == Vec3{1, 0, 0};
    EXPECT_EQ(prop[f], has_v1 ? 1 : 0) << "face " << f.idx();
  }
  RenderBuffers rs(m);
  ASSERT_EQ(rs.submesh_count(), 2u);
  EXPECT_EQ(rs.submesh(0).max, (Vec3{1, 1, 0}));
  EXPECT_EQ(rs.submesh(0).min, (Vec3{0, 0, 0}));
  EXPECT_EQ(rs.submesh(1).min, (Vec3{0, 0, 0}));
  EXPECT_TRUE(m.validate().empty());

  auto message = [&](std::vector<std::int32_t> s) -> std::string {
    EngineMeshView w{p, ix};
    w.submeshes = s;
    try {
      from_engine_mesh(w);
    } catch (const InvalidInputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message({0, 1}).find("submeshes has 2 entries for 3 triangles"), std::string::npos);
  EXPECT_NE(message({0, -1, 0}).find("submesh of triangle 1 is -1"), std::string::npos);
  EXPECT_FALSE(static_cast<bool>(from_engine_mesh({p, ix}).get_face_property<std::int32_t>("f:submesh")));
}

// A flat quad of two triangles at z = 0 with imported normals (0, 0, 1), tangents along x and a
// second texcoord channel that differs per vertex.
struct TangentQuad {
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  std::vector<std::uint32_t> ix = {0, 1, 2, 0, 2, 3};
  std::vector<Vec3> n = std::vector<Vec3>(4, Vec3{0, 0, 1});
  std::vector<Vec4> t = std::vector<Vec4>(4, Vec4{1, 0, 0, -1});
  std::vector<Vec2> uv1 = {{0, 0}, {0.5f, 0}, {0.5f, 0.5f}, {0, 0.5f}};
  EngineMeshView view() const {
    EngineMeshView v{p, ix, n};
    v.tangents = t;
    v.texcoords1 = uv1;
    return v;
  }
};

TEST(EngineMesh, TangentsAndSecondTexcoordsReachTheBuffers) {
  TangentQuad q;
  SurfaceMesh m = from_engine_mesh(q.view());
  ASSERT_TRUE(m.get_halfedge_property<Vec4>("h:tangent"));
  ASSERT_TRUE(m.get_halfedge_property<Vec2>("h:texcoord1"));
  for (bool interleaved : {true, false}) {
    RenderOptions o;
    o.interleaved = interleaved;
    RenderBuffers rs(m, o);
    const VertexLayout& l = rs.layout();
    ASSERT_GE(l.tangent, 0);
    ASSERT_GE(l.texcoord1, 0);
    EXPECT_EQ(l.stride, 3u + 3u + 4u + 2u);
    for (std::size_t rv = 0; rv < rs.vertex_slots(); ++rv) {
      const float* tangent =
          interleaved ? rs.vertices().data() + rv * l.stride + l.tangent : rs.tangents().data() + 4 * rv;
      const float* uv1 =
          interleaved ? rs.vertices().data() + rv * l.stride + l.texcoord1 : rs.texcoords1().data() + 2 * rv;
      const float* pos = rs.vertices().data() + rv * (interleaved ? l.stride : 3);
      EXPECT_EQ((Vec4{tangent[0], tangent[1], tangent[2], tangent[3]}), (Vec4{1, 0, 0, -1}));
      EXPECT_EQ(uv1[0], pos[0] / 2);
      EXPECT_EQ(uv1[1], pos[1] / 2);
    }
  }
  RenderOptions none;
  none.tangents = none.texcoords1 = false;
  EXPECT_EQ(RenderBuffers(m, none).layout().tangent, -1);
  // A mirror negates x and the handedness.
  EngineImportOptions mirrored;
  mirrored.flip_x = true;
  SurfaceMesh f = from_engine_mesh(q.view(), mirrored);
  EXPECT_EQ(f.get_halfedge_property<Vec4>("h:tangent")[*f.halfedges().begin()], (Vec4{-1, 0, 0, 1}));
}

// Where normals follow the geometry, the tangents of the corners whose normal changed are made
// perpendicular to it again, unit length, handedness kept; a split's new corners too.
TEST(EngineMesh, TangentsStayPerpendicularToNormalsThatFollowEdits) {
  TangentQuad q;
  SurfaceMesh m = from_engine_mesh(q.view());
  RenderBuffers rs(m);
  auto normal = m.get_halfedge_property<Vec3>("h:normal");
  auto tangent = m.get_halfedge_property<Vec4>("h:tangent");
  auto check = [&](const char* what) {
    for (Face f : m.faces())
      for (Halfedge h : m.halfedges(f)) {
        const Vec4 t = tangent[h];
        const Vec3 t3{t.x, t.y, t.z};
        EXPECT_NEAR(dot(t3, normal[h]), 0, 1e-6) << what;
        EXPECT_NEAR(norm(t3), 1, 1e-6) << what;
        EXPECT_EQ(t.w, -1.f) << what;
        const std::size_t stride = rs.layout().stride;
        const float* b = rs.vertices().data() + rs.render_vertex(h) * stride + rs.layout().tangent;
        EXPECT_EQ((Vec4{b[0], b[1], b[2], b[3]}), t) << what << ": the buffers show the mesh's tangent";
      }
  };
  Vertex v0, v2;
  for (Vertex v : m.vertices()) {
    if (m.position(v) == Vec3{0, 0, 0}) v0 = v;
    if (m.position(v) == Vec3{1, 1, 0}) v2 = v;
  }
  m.set_position(v2, Vec3{1, 1, 1});
  rs.sync();
  check("after a move");
  bool tilted = false;
  for (Halfedge h : m.halfedges()) tilted |= !m.is_boundary(h) && std::abs(tangent[h].z) > 0.1f;
  EXPECT_TRUE(tilted) << "the tangents followed the tilted normals";
  const Halfedge d = m.find_halfedge(v0, v2);  // the diagonal
  ASSERT_TRUE(d.is_valid());
  split_edge(m, SurfaceMesh::edge(d), (m.position(m.from_vertex(d)) + m.position(v2)) * 0.5f);
  rs.sync();
  check("after a split");
  EXPECT_TRUE(m.validate().empty());
}

TEST(EngineMesh, BadTangentsAreRejectedWithAClearMessage) {
  TangentQuad q;
  auto message = [](const EngineMeshView& v) -> std::string {
    try {
      from_engine_mesh(v);
    } catch (const InvalidInputError& e) {
      return e.what();
    }
    return "";
  };
  EngineMeshView v = q.view();
  std::vector<Vec4> one(1);
  v.tangents = one;
  EXPECT_NE(message(v).find("tangents has 1 entries for 4 vertices"), std::string::npos) << message(v);
  std::vector<Vec4> nan_t = q.t;
  nan_t[2].w = NAN;
  v.tangents = nan_t;
  EXPECT_NE(message(v).find("tangent of vertex 2"), std::string::npos) << message(v);
  std::vector<Vec2> short_uv1(3);
  v = q.view();
  v.texcoords1 = short_uv1;
  EXPECT_NE(message(v).find("texcoords1 has 3 entries"), std::string::npos) << message(v);
}

TEST(EngineMesh, OrthogonalTangent) {
  const Vec4 t = orthogonal_tangent(Vec4{1, 0, 1, 0.3f}, Vec3{0, 0, 1});
  EXPECT_EQ(t, (Vec4{1, 0, 0, 1}));
  EXPECT_EQ(orthogonal_tangent(Vec4{0, 0, 2, -1}, Vec3{0, 0, 1}), (Vec4{0, 0, 1, -1}));  // along n: kept
}

// The map back to the engine arrays: every corner names its engine vertex (the triangle's own
// index), every vertex the smallest engine vertex welded into it; after a split the new vertex and
// its corners name none, and the old ones keep theirs through garbage collection.
TEST(EngineMesh, SourceIndicesMapBackToTheEngineVertices) {
  const EngineMesh e =
      engine_mesh_from(read_indexed_file(std::string(HEDGE_DATA_DIR) + "/spot_triangulated.obj"));
  BuildReport report;
  SurfaceMesh m = from_engine_mesh(e.view(), {}, &report);
  auto corner = m.get_halfedge_property<std::int32_t>(kCornerSource);
  auto vertex = m.get_vertex_property<std::int32_t>(kVertexSource);
  ASSERT_TRUE(corner && vertex);
  std::vector<std::int32_t> smallest(m.vertex_slots(), -1);
  for (std::size_t t = 0; t < e.indices.size() / 3; ++t) {
    const Face f(report.face_map[t]);
    for (Halfedge h : m.halfedges(f)) {
      const std::int32_t s = corner[h];
      ASSERT_GE(s, 0);
      EXPECT_TRUE(s == std::int32_t(e.indices[3 * t]) || s == std::int32_t(e.indices[3 * t + 1]) ||
                  s == std::int32_t(e.indices[3 * t + 2]))
          << "triangle " << t;
      EXPECT_EQ(e.positions[s], m.position(m.to_vertex(h)));
      std::int32_t& low = smallest[m.to_vertex(h).idx()];
      if (low < 0 || s < low) low = s;
    }
  }
  for (Vertex v : m.vertices()) EXPECT_EQ(vertex[v], smallest[v.idx()]) << "vertex " << v.idx();
  for (Halfedge h : m.halfedges())
    if (m.is_boundary(h)) EXPECT_EQ(corner[h], -1);

  const Vertex a = m.from_vertex(m.halfedge(Face(0))), b = m.to_vertex(m.halfedge(Face(0)));
  const std::int32_t a_source = vertex[a], b_source = vertex[b];
  const Vertex added = split_edge(m, m.edge(m.halfedge(Face(0))), 0.5f * (m.position(a) + m.position(b)));
  ASSERT_TRUE(added.is_valid());
  EXPECT_EQ(vertex[added], -1);
  for (Halfedge h : m.halfedges(added))
    if (!m.is_boundary(SurfaceMesh::twin(h))) EXPECT_EQ(corner[SurfaceMesh::twin(h)], -1);
  ASSERT_TRUE(remove_face(m, Face(5)));
  const GarbageMaps maps = m.garbage_collection();
  EXPECT_TRUE(m.validate().empty());
  EXPECT_EQ(vertex[Vertex(maps.vertices[a.idx()])], a_source);
  EXPECT_EQ(vertex[Vertex(maps.vertices[b.idx()])], b_source);
}

}  // namespace
}  // namespace hedge
