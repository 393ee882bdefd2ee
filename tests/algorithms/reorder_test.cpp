#include "hedge/algorithms/reorder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "hedge/core/build.h"
#include "hedge/core/changes.h"
#include "hedge/core/operations.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
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
  const GarbageMaps maps = reorder_spatially(m);
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
  reorder_spatially(m);
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
  reorder_spatially(m);
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

}  // namespace
}  // namespace hedge
