// The per-mesh picking tree and busy check of the binding core (src/binding/mesh_state.cpp).
#include "binding/mesh_state.h"

#include <gtest/gtest.h>

#include <memory>
#include <thread>

#include "binding/errors.h"
#include "hedge/core/build.h"
#include "hedge/core/face_operations.h"
#include "test_meshes.h"

namespace hedge::binding {
namespace {

TEST(BindingMeshState, OnePickingTreeKeptUpToDate) {
  MeshState s;
  s.mesh = build(test::grid(4, true));
  const std::size_t bare = memory_bytes(s);
  FaceBvh& tree = picking_tree(s);
  EXPECT_GT(memory_bytes(s), bare);
  ASSERT_TRUE(split_face(s.mesh, Face(0), face_centroid(s.mesh, Face(0))).is_valid());
  EXPECT_FALSE(tree.up_to_date());
  EXPECT_EQ(&picking_tree(s), &tree) << "updated, not rebuilt";
  EXPECT_TRUE(tree.up_to_date());
  EXPECT_EQ(tree.stats().live_faces, s.mesh.n_faces());
  EXPECT_TRUE(s.mesh.validate().empty());
}

TEST(BindingMeshState, AnotherThreadsClaimIsBusy) {
  auto s = std::make_shared<MeshState>();
  {
    MeshUse<MeshState> use(s);
    MeshUse<MeshState> nested(s);  // the same thread again
    hedge_status other = HEDGE_OK;
    std::thread([&] {
      try {
        MeshUse<MeshState> second(s);
      } catch (const BindingError& e) {
        other = e.status;
      }
    }).join();
    EXPECT_EQ(other, HEDGE_ERROR_BUSY);
  }
  hedge_status later = HEDGE_ERROR_INTERNAL;
  std::thread([&] {
    MeshUse<MeshState> free_now(s);
    later = HEDGE_OK;
  }).join();
  EXPECT_EQ(later, HEDGE_OK) << "released by the last use";
}

}  // namespace
}  // namespace hedge::binding
