#include "hedge/algorithms/reorder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <numeric>
#include <random>
#include <vector>

#include "hedge/core/build.h"
#include "hedge/core/changes.h"
#include "hedge/core/face_operations.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "non_finite.h"
#include "test_meshes.h"

namespace hedge {
namespace {

// Every face as the sorted positions of its corners, for comparing meshes whatever their order.
std::vector<std::vector<float>> faces_by_position(const SurfaceMesh& m) {
  std::vector<std::vector<float>> out;
  for (Face f : m.faces()) {
    std::vector<float> key;
    for (Vertex v : m.vertices(f)) key.insert(key.end(), {m.position(v).x, m.position(v).y, m.position(v).z});
    out.push_back(key);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// A mesh whose vertices and faces are in a random order.
SurfaceMesh shuffled(const IndexedMesh& in, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<Index> perm(in.positions.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  IndexedMesh out;
  out.positions.resize(in.positions.size());
  for (std::size_t i = 0; i < perm.size(); ++i) out.positions[perm[i]] = in.positions[i];
  std::vector<std::size_t> faces(in.indices.size() / 3);
  std::iota(faces.begin(), faces.end(), 0);
  std::shuffle(faces.begin(), faces.end(), rng);
  for (std::size_t f : faces)
    for (int k = 0; k < 3; ++k) out.indices.push_back(perm[in.indices[3 * f + k]]);
  return build(out);
}

// The mean distance in memory between a vertex and its neighbours, in indices.
double mean_neighbour_gap(const SurfaceMesh& m) {
  double sum = 0, n = 0;
  for (Vertex v : m.vertices())
    for (Vertex w : m.vertices(v)) sum += std::abs(double(v.idx()) - double(w.idx())), n += 1;
  return sum / n;
}

TEST(Reorder, ShuffledMeshGetsItsLocalityBackWithTheSameSurface) {
  const IndexedMesh spot = read_indexed_file(test::data_path("spot_triangulated.obj"));
  SurfaceMesh m = shuffled(spot, 11);
  const auto before = faces_by_position(m);
  const double gap_before = mean_neighbour_gap(m);
  const GarbageMaps maps = reorder(m);
  EXPECT_EQ(faces_by_position(m), before);
  EXPECT_LT(mean_neighbour_gap(m), 0.1 * gap_before);
  EXPECT_EQ(maps.vertices.size(), m.vertex_slots());
  EXPECT_TRUE(m.validate().empty()) << m.validate().front();
}

TEST(Reorder, FacesMeetTheirEdgesInOrderAndPropertiesFollow) {
  SurfaceMesh m = shuffled(read_indexed_file(test::data_path("spot_triangulated.obj")), 5);
  auto tag = m.add_face_property<int>("f:tag", 0);
  auto at = m.add_vertex_property<Vec3>("v:copy");
  for (Face f : m.faces()) tag[f] = int(f.idx());
  for (Vertex v : m.vertices()) at[v] = m.position(v);
  std::vector<Vec3> centroid_of_tag(m.n_faces());
  for (Face f : m.faces()) {
    Vec3 c{0, 0, 0};
    for (Vertex v : m.vertices(f)) c += m.position(v) * (1.f / 3);
    centroid_of_tag[std::size_t(tag[f])] = c;
  }
  const ChangeConsumer watch(m.watch_changes());
  reorder(m);
  EXPECT_TRUE(watch.pending().reset);
  const auto tag2 = m.get_face_property<int>("f:tag");
  const auto at2 = m.get_vertex_property<Vec3>("v:copy");
  for (Vertex v : m.vertices()) EXPECT_EQ(at2[v], m.position(v));
  for (Face f : m.faces()) {
    Vec3 c{0, 0, 0};
    for (Vertex v : m.vertices(f)) c += m.position(v) * (1.f / 3);
    EXPECT_EQ(c, centroid_of_tag[std::size_t(tag2[f])]);
  }
  // Edges are numbered as the faces meet them: face 0's edges come first.
  for (Halfedge h : m.halfedges(Face(0))) EXPECT_LT(SurfaceMesh::edge(h).idx(), 3u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Reorder, GarbageIsCollectedAndBadNumberingsAreRefused) {
  SurfaceMesh m = build(test::grid(4, true));
  Face removable;
  for (Face f : m.faces())
    if (can_remove_face(m, f)) removable = f;
  ASSERT_TRUE(remove_face(m, removable));
  const std::size_t faces = m.n_faces();
  reorder(m);
  EXPECT_FALSE(m.has_garbage());
  EXPECT_EQ(m.n_faces(), faces);
  EXPECT_TRUE(m.validate().empty());

  std::vector<Index> v(m.vertex_slots()), e(m.edge_slots()), f(m.face_slots());
  std::iota(v.begin(), v.end(), 0);
  std::iota(e.begin(), e.end(), 0);
  std::iota(f.begin(), f.end(), 0);
  auto twice = v;
  twice[1] = 0;
  EXPECT_THROW(m.renumber(twice, e, f), InvalidInputError);
  EXPECT_THROW(m.renumber(v, std::vector<Index>(3, 0), f), InvalidInputError);
  auto beyond = f;
  beyond[0] = Index(f.size());
  EXPECT_THROW(m.renumber(v, e, beyond), InvalidInputError);
  EXPECT_TRUE(m.validate().empty());
  // The identity is a valid numbering.
  m.renumber(v, e, f);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Reorder, VertexCacheOrderLoadsFewVerticesPerTriangleAndKeepsTheSurface) {
  const IndexedMesh spot = read_indexed_file(test::data_path("spot_triangulated.obj"));
  SurfaceMesh m = shuffled(spot, 3);
  auto tag = m.add_face_property<int>("f:tag", 0);
  for (Face f : m.faces()) tag[f] = int(f.idx());
  const auto before = faces_by_position(m);
  const double shuffled_acmr = average_cache_miss_ratio(m, 16);
  EXPECT_GT(shuffled_acmr, 2.5);  // a random order misses nearly every corner
  const GarbageMaps maps = reorder(m, Ordering::vertex_cache, 16);
  EXPECT_EQ(faces_by_position(m), before);
  const double acmr = average_cache_miss_ratio(m, 16);
  // A closed triangle mesh has about twice as many faces as vertices, so every order needs at least
  // V / F ~ 0.5 loads per triangle; a fan order with a 16-entry cache gets within about 0.2 of it.
  EXPECT_GE(acmr, double(m.n_vertices()) / double(m.n_faces()));
  EXPECT_LT(acmr, 0.75);
  SurfaceMesh spatial = shuffled(spot, 3);
  reorder(spatial, Ordering::spatial);
  EXPECT_LT(acmr, average_cache_miss_ratio(spatial, 16));
  // Vertices are numbered by first use: face 0 uses vertices 0, 1, 2, and no face uses a vertex
  // beyond one more than the highest used before it.
  Index highest = 0;
  for (Face f : m.faces())
    for (Vertex v : m.vertices(f)) {
      EXPECT_LE(v.idx(), highest + 1);
      highest = std::max(highest, v.idx());
    }
  // The maps are permutations and the face property followed its faces.
  const auto tag2 = m.get_face_property<int>("f:tag");
  for (std::size_t f = 0; f < maps.faces.size(); ++f) EXPECT_EQ(tag2[Face(maps.faces[f])], int(f));
  EXPECT_TRUE(m.validate().empty());
}

TEST(Reorder, VertexCacheOrderTakesPolygonsBoundariesIsolatedVerticesAndGarbage) {
  SurfaceMesh m = build(test::grid(6, false));  // quads with a boundary
  const Vertex lone = m.add_vertex(Vec3{9, 9, 9});
  Face removable;
  for (Face f : m.faces())
    if (can_remove_face(m, f)) removable = f;
  ASSERT_TRUE(remove_face(m, removable));
  const std::size_t faces = m.n_faces(), vertices = m.n_vertices();
  const GarbageMaps maps = reorder(m, Ordering::vertex_cache, 8);
  EXPECT_FALSE(m.has_garbage());
  EXPECT_EQ(m.n_faces(), faces);
  EXPECT_EQ(m.n_vertices(), vertices);
  EXPECT_EQ(maps.faces[removable.idx()], kInvalidIndex);
  EXPECT_EQ(maps.vertices[lone.idx()], Index(vertices - 1));  // isolated vertices last
  EXPECT_TRUE(m.is_isolated(Vertex(Index(vertices - 1))));
  EXPECT_TRUE(m.validate().empty());

  SurfaceMesh empty;
  EXPECT_TRUE(reorder(empty, Ordering::vertex_cache).vertices.empty());
  EXPECT_EQ(average_cache_miss_ratio(empty), 0.0);
  EXPECT_TRUE(empty.validate().empty());
}

TEST(Reorder, CacheMissRatioCountsFifoLoads) {
  // Two triangles sharing an edge: 4 loads for 2 triangles with any cache of 3 or more entries;
  // with a single entry every corner after the first of a run misses.
  IndexedMesh two;
  two.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  two.indices = {0, 1, 2, 0, 2, 3};
  const SurfaceMesh m = build(two);
  EXPECT_DOUBLE_EQ(average_cache_miss_ratio(m, 16), 2.0);
  EXPECT_DOUBLE_EQ(average_cache_miss_ratio(m, 1), 3.0);
  // A cache of k entries keeps a vertex until k others entered after it: the ratio is that of a
  // FIFO queue of k vertices, each triangle drawn from its face's half-edge target on.
  const SurfaceMesh grid = build(test::grid(6, true));
  for (std::size_t k : {1, 2, 3, 5, 16}) {
    std::deque<Vertex> fifo;
    std::size_t misses = 0;
    for (Face f : grid.faces()) {
      const Halfedge h = grid.halfedge(f);
      for (Vertex v :
           {grid.to_vertex(h), grid.to_vertex(grid.next(h)), grid.to_vertex(grid.next(grid.next(h)))}) {
        if (std::find(fifo.begin(), fifo.end(), v) != fifo.end()) continue;
        ++misses;
        fifo.push_back(v);
        if (fifo.size() > k) fifo.pop_front();
      }
    }
    EXPECT_DOUBLE_EQ(average_cache_miss_ratio(grid, k), double(misses) / double(grid.n_faces())) << k;
  }
  // A quad draws as a fan of two triangles: 4 loads.
  SurfaceMesh quad = build(test::grid(1, false));
  EXPECT_DOUBLE_EQ(average_cache_miss_ratio(quad, 16), 2.0);
}

TEST(Reorder, SpatialOrderRefusesANonFinitePosition) {
  SurfaceMesh m = build(test::grid(6, true));
  test::expect_refuses_non_finite(m, Vertex(9), "reorder", [&] { reorder(m, Ordering::spatial); });
}

}  // namespace
}  // namespace hedge
