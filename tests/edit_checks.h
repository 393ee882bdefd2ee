// What the tests of the mesh edits check besides validate(): element counts, everything observable
// about a mesh (to see that a refused edit changed nothing), and a mesh whose properties show
// whether an edit carried them along.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "edits/random_edits.h"
#include "hedge/core/build.h"
#include "hedge/core/surface_mesh.h"
#include "test_meshes.h"

namespace hedge::test {

struct Counts {
  long long v, e, f;
  long long chi() const { return v - e + f; }
};
inline Counts counts(const SurfaceMesh& m) {
  return {static_cast<long long>(m.n_vertices()), static_cast<long long>(m.n_edges()),
          static_cast<long long>(m.n_faces())};
}

// Everything observable about a mesh: connectivity, deletion state, positions and a test property.
struct Snapshot {
  std::vector<Vertex> hv;
  std::vector<Halfedge> hn;
  std::vector<Face> hf;
  std::vector<Halfedge> vh, fh;
  std::vector<bool> vdel, edel, fdel;
  std::vector<Vec3> pos;
  std::vector<Vec2> uv;
  std::vector<float> weight;
  bool operator==(const Snapshot&) const = default;
};
inline Snapshot snapshot(const SurfaceMesh& m) {
  Snapshot s;
  s.hv = m.halfedge_vertex_array();
  s.hn = m.halfedge_next_array();
  s.hf = m.halfedge_face_array();
  for (Index i = 0; i < m.vertex_slots(); ++i) {
    s.vh.push_back(m.halfedge(Vertex(i)));
    s.vdel.push_back(m.is_deleted(Vertex(i)));
    s.pos.push_back(m.position(Vertex(i)));
  }
  for (Index i = 0; i < m.face_slots(); ++i) {
    s.fh.push_back(m.halfedge(Face(i)));
    s.fdel.push_back(m.is_deleted(Face(i)));
  }
  for (Index i = 0; i < m.edge_slots(); ++i) s.edel.push_back(m.is_deleted(Edge(i)));
  if (auto uv = m.get_halfedge_property<Vec2>("h:texcoord")) s.uv = uv.vector();
  if (auto w = m.get_vertex_property<float>("v:weight")) s.weight = w.vector();
  return s;
}

// A grid whose corners carry their xy position as texcoord, and vertices a weight = x.
inline SurfaceMesh textured_grid(int n, bool tri) {
  IndexedMesh in = test::grid(n, tri);
  for (Index i : in.indices) {
    in.texcoord_indices.push_back(static_cast<Index>(in.texcoords.size()));
    in.texcoords.push_back({in.positions[i].x, in.positions[i].y});
  }
  SurfaceMesh m = build(in);
  auto w = m.add_vertex_property<float>("v:weight");
  for (Vertex v : m.vertices()) w[v] = m.position(v).x;
  return m;
}

inline void expect_corner_uv_matches_position(const SurfaceMesh& m) {
  auto uv = m.get_halfedge_property<Vec2>("h:texcoord");
  for (Face f : m.faces())
    for (Halfedge h : m.halfedges(f)) {
      const Vec3 p = m.position(m.to_vertex(h));
      EXPECT_NEAR(uv[h].x, p.x, 1e-5f);
      EXPECT_NEAR(uv[h].y, p.y, 1e-5f);
    }
}

// Calls check(m) on m as it is and after each of `steps` seeded random edits (tools/edits/random_edits.h).
template <typename Check>
void after_random_edits(SurfaceMesh& m, std::uint64_t seed, int steps, Check&& check) {
  RandomEditor editor(m, seed);
  check(m);
  for (int i = 0; i < steps; ++i) {
    editor.step();
    check(m);
  }
}

// Expects an edit's predicate, its refusal, the conditions its documentation states (`contract`,
// written in the test from the mesh's queries) and the edit itself (done on a copy of m; edit(copy)
// says whether it was done) to agree: the predicate holds, the contract holds and the edit is done
// exactly when the refusal is null.
template <typename Edit>
void expect_refusal_agrees(const SurfaceMesh& m, bool predicate, bool contract, const char* refusal,
                           Edit&& edit, const std::string& what) {
  EXPECT_EQ(predicate, refusal == nullptr) << what << ": " << (refusal ? refusal : "allowed");
  EXPECT_EQ(contract, refusal == nullptr) << what << ": " << (refusal ? refusal : "allowed");
  SurfaceMesh copy = m;
  EXPECT_EQ(edit(copy), refusal == nullptr) << what << ": " << (refusal ? refusal : "allowed");
  EXPECT_TRUE(copy.validate().empty()) << what;
}

}  // namespace hedge::test
