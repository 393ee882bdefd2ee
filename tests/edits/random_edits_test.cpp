#include "edits/random_edits.h"

#include <gtest/gtest.h>

#include "hedge/core/operations.h"
#include "hedge/io/io.h"
#include "test_meshes.h"

namespace hedge {
namespace {

// Release builds run the long sequences (over a million operations across the suite) and
// validate periodically; debug and sanitizer builds run shorter ones and validate after every
// operation.
#ifdef NDEBUG
constexpr std::size_t kOps = 260000;
constexpr std::size_t kValidateEvery = 1000;
#else
constexpr std::size_t kOps = 3000;
constexpr std::size_t kValidateEvery = 1;
#endif

struct Case {
  const char* file;
  const char* kind;
};

class RandomEdits : public ::testing::TestWithParam<Case> {};

TEST_P(RandomEdits, StayValidAndKeepEuler) {
  SurfaceMesh m = read_mesh(test::data_path(GetParam().file));
  ASSERT_TRUE(m.validate().empty());
  RandomEditOptions o;
  o.seed = 20261122;
  o.operations = kOps;
  o.validate_every = kValidateEvery;
  o.collect_every = 2500;
  RandomEditReport r = random_edits(m, o);
  EXPECT_TRUE(r.valid) << edit_name(r.first_invalid_kind) << " at operation " << r.first_invalid_operation
                       << ": " << (r.problems.empty() ? "" : r.problems.front());
  EXPECT_EQ(r.euler_mismatches, 0u);
  EXPECT_EQ(r.total_applied() + r.total_refused(), kOps);
  // Every kind that can apply to this mesh did.
  for (EditKind k : {EditKind::split_edge, EditKind::collapse, EditKind::split_face, EditKind::remove_face,
                     EditKind::remove_vertex})
    EXPECT_GT(r.applied[static_cast<std::size_t>(k)], 0u) << edit_name(k);
  EXPECT_TRUE(m.validate().empty());
}

INSTANTIATE_TEST_SUITE_P(DataMeshes, RandomEdits,
                         ::testing::Values(Case{"anchor.off", "closed genus 4"},
                                           Case{"bob_small.ply", "closed genus 1"},
                                           Case{"elephant-with-holes.off", "open, 100+ holes"},
                                           Case{"spot_control_mesh.obj", "polygons"}),
                         [](const auto& info) {
                           std::string n = info.param.file;
                           for (char& c : n)
                             if (!isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(RandomEditsDeterminism, SameSeedSameMesh) {
  SurfaceMesh a = read_mesh(test::data_path("spot_control_mesh.obj"));
  SurfaceMesh b = a;
  RandomEditOptions o;
  o.seed = 99;
  o.operations = 3000;
  RandomEditReport ra = random_edits(a, o), rb = random_edits(b, o);
  EXPECT_EQ(ra.applied, rb.applied);
  EXPECT_EQ(a.halfedge_vertex_array(), b.halfedge_vertex_array());
  EXPECT_EQ(a.halfedge_next_array(), b.halfedge_next_array());
  o.seed = 100;
  SurfaceMesh c = read_mesh(test::data_path("spot_control_mesh.obj"));
  random_edits(c, o);
  EXPECT_NE(a.halfedge_vertex_array(), c.halfedge_vertex_array());
  EXPECT_TRUE(a.validate().empty());
  EXPECT_TRUE(c.validate().empty());
}

class CollapseUntilRefused : public ::testing::TestWithParam<const char*> {};

TEST_P(CollapseUntilRefused, EndsValid) {
  SurfaceMesh m = read_mesh(test::data_path(GetParam()));
  const long long chi = static_cast<long long>(m.n_vertices()) - static_cast<long long>(m.n_edges()) +
                        static_cast<long long>(m.n_faces());
  std::size_t collapses = 0;
  for (bool any = true; any;) {
    any = false;
    for (Halfedge h : m.halfedges())
      if (collapse(m, h).is_valid()) {
        any = true;
        ++collapses;
      }
  }
  EXPECT_GT(collapses, 0u);
  EXPECT_TRUE(m.validate().empty());
  EXPECT_EQ(static_cast<long long>(m.n_vertices()) - static_cast<long long>(m.n_edges()) +
                static_cast<long long>(m.n_faces()),
            chi);
  m.garbage_collection();
  EXPECT_TRUE(m.validate().empty());
  for (Halfedge h : m.halfedges()) EXPECT_FALSE(can_collapse(m, h));
}

INSTANTIATE_TEST_SUITE_P(DataMeshes, CollapseUntilRefused,
                         ::testing::Values("anchor.off", "bob_small.ply", "spot_control_mesh.obj",
                                           "fandisk_quads.off", "three_peaks.off", "moebius.obj"),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (!isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

}  // namespace
}  // namespace hedge
