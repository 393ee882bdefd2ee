#include "hedge/algorithms/fill_hole.h"

#include <gtest/gtest.h>

#include "edit_checks.h"
#include "hedge/core/build.h"
#include "hedge/core/operations.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using test::Counts;
using test::counts;

TEST(RemoveVertex, InteriorVertexLeavesAHoleThatFillHoleCloses) {
  SurfaceMesh m = build(test::grid(4, true));
  Counts before = counts(m);
  Vertex v(12);  // the centre
  std::size_t ring = m.valence(v);
  Halfedge outer = m.next(m.halfedge(v));
  ASSERT_TRUE(remove_vertex(m, v));
  EXPECT_TRUE(m.is_deleted(v));
  EXPECT_EQ(m.boundary_loops().size(), 2u);
  EXPECT_EQ(counts(m).f, before.f - static_cast<long long>(ring));
  EXPECT_TRUE(m.validate().empty());
  auto faces = fill_hole(m, outer);
  EXPECT_EQ(faces.size(), ring - 2);
  EXPECT_EQ(m.boundary_loops().size(), 1u);
  EXPECT_EQ(counts(m).chi(), before.chi() - 1 + 1);
  EXPECT_TRUE(m.is_triangle_mesh());
  EXPECT_TRUE(m.validate().empty());
}

TEST(FillHole, OuterLoopOfAGridMakesASphere) {
  SurfaceMesh m = build(test::grid(3, false));
  auto loops = m.boundary_loops();
  ASSERT_EQ(loops.size(), 1u);
  auto faces = fill_hole(m, loops[0]);
  EXPECT_FALSE(faces.empty());
  EXPECT_TRUE(m.boundary_loops().empty());
  EXPECT_EQ(counts(m).chi(), 2);
  EXPECT_TRUE(m.validate().empty());
  EXPECT_TRUE(fill_hole(m, m.halfedge(Face(0))).empty());  // not a boundary half-edge
}

}  // namespace
}  // namespace hedge
