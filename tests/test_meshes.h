// Small meshes built in code, shared by the tests.
#pragma once

#include <string>
#include <vector>

#include "hedge/core/build.h"
#include "hedge/core/indexed_mesh.h"
#include "hedge/core/surface_mesh.h"

namespace hedge::test {

//! A closed tetrahedron, consistently oriented (outward normals, CCW).
inline IndexedMesh tetrahedron() {
  IndexedMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  return m;
}

//! The 7-vertex, 6-triangle example of the half-edge article (OBJ indices made 0-based).
inline IndexedMesh article_example() {
  IndexedMesh m;
  m.positions = {{1, 4, 0}, {3, 4, 0}, {0, 2, 0}, {2, 2, 0}, {4, 2, 0}, {1, 0, 0}, {3, 0, 0}};
  m.indices = {0, 2, 3, 0, 3, 1, 1, 3, 4, 2, 5, 3, 3, 5, 6, 3, 6, 4};
  return m;
}

//! An n x n grid of quads (open, one boundary loop); triangulated when tri is true.
inline IndexedMesh grid(int n, bool tri) {
  IndexedMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back({float(i), float(j), 0.f});
  auto id = [&](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      Index a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (tri) {
        m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
      } else {
        m.indices.insert(m.indices.end(), {a, b, c, d});
        m.face_sizes.push_back(4);
      }
    }
  return m;
}

//! A closed cube of 6 quads.
inline IndexedMesh cube() {
  IndexedMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  m.indices = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
  m.face_sizes = {4, 4, 4, 4, 4, 4};
  return m;
}

//! A patch of the regular triangular lattice, (n + 1) x (n + 1) vertices in z = 0, rows offset by
//! half a step: every interior vertex has valence 6 and every angle is 60 degrees.
inline IndexedMesh triangle_lattice(int n) {
  IndexedMesh in;
  const float h = 0.8660254f;  // sqrt(3) / 2
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) in.positions.push_back({float(i) + 0.5f * float(j % 2), h * float(j), 0});
  auto id = [&](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Index a = id(i, j), b = id(i + 1, j), c = id(i, j + 1), d = id(i + 1, j + 1);
      if (j % 2 == 0) {
        in.indices.insert(in.indices.end(), {a, b, c, b, d, c});
      } else {
        in.indices.insert(in.indices.end(), {a, b, d, a, d, c});
      }
    }
  return in;
}

//! The first edge of `m` for which `pick(e)` holds, or an invalid edge.
template <typename Pick>
Edge first_edge(const SurfaceMesh& m, Pick&& pick) {
  for (Edge e : m.edges())
    if (pick(e)) return e;
  return Edge();
}

inline std::string data_path(const std::string& name) { return std::string(HEDGE_DATA_DIR) + "/" + name; }
inline std::string shared_mesh_path(const std::string& name) {
  return std::string(HEDGE_SHARED_MESHES_DIR) + "/" + name;
}

}  // namespace hedge::test
