#include "hedge/core/refusal.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "hedge/algorithms/fill_hole.h"
#include "hedge/core/operations.h"
#include "test_meshes.h"

namespace hedge {
namespace {

// Every refusal of the table: code i at entry i, one name and one text per code, and the text maps
// back to its code whether it is the table's pointer or a copy of its characters.
TEST(RefusalTable, EveryTextMapsToExactlyOneCode) {
  ASSERT_EQ(refusals().size(), static_cast<std::size_t>(kRefusalCount));
  std::set<std::string> names, texts;
  for (std::int32_t i = 0; i < kRefusalCount; ++i) {
    const RefusalEntry& r = refusals()[i];
    EXPECT_EQ(static_cast<std::int32_t>(r.code), i);
    EXPECT_TRUE(names.insert(r.name).second) << "name repeated: " << r.name;
    EXPECT_TRUE(texts.insert(r.text).second) << "text repeated: " << r.text;
    EXPECT_EQ(refusal_text(r.code), r.text);
    EXPECT_EQ(refusal_code(r.text), r.code) << r.text;
    const std::string copy = r.text;
    EXPECT_EQ(refusal_code(copy.c_str()), r.code) << "by content: " << r.text;
    if (i > 0) EXPECT_NE(std::string(r.text), "") << r.name;
  }
  EXPECT_STREQ(refusals()[0].name, "none");
  EXPECT_EQ(refusal_code(nullptr), Refusal::none);
  EXPECT_EQ(refusal_code(""), Refusal::none);
  EXPECT_EQ(refusal_code("not a refusal of the library"), Refusal::none);
  EXPECT_STREQ(refusal_text(static_cast<Refusal>(-1)), "");
  EXPECT_STREQ(refusal_text(static_cast<Refusal>(kRefusalCount)), "");
}

// The edits' refusals are the table's own strings (the same pointers), one of each kind of edit.
TEST(RefusalTable, EditsReturnTheTablesTexts) {
  SurfaceMesh tet = build(test::tetrahedron());
  SurfaceMesh square = build(test::grid(1, true));
  Edge open;
  for (Index e = 0; e < square.edge_slots() && !open.is_valid(); ++e)
    if (square.is_boundary(Edge(e))) open = Edge(e);
  ASSERT_TRUE(open.is_valid());
  EXPECT_EQ(flip_refusal(square, open), refusal_text(Refusal::flip_boundary_edge));
  EXPECT_EQ(flip_refusal(tet, Edge(0)), refusal_text(Refusal::flip_valence_three));
  EXPECT_EQ(flip_refusal(tet, Edge(99)), refusal_text(Refusal::edge_not_live));
  EXPECT_EQ(split_refusal(tet, Edge(99)), refusal_text(Refusal::edge_not_live));
  EXPECT_EQ(collapse_refusal(tet, Halfedge(0)), refusal_text(Refusal::collapse_tip_too_few_edges));
  EXPECT_EQ(collapse_refusal(tet, Halfedge(99)), refusal_text(Refusal::halfedge_not_live));
  EXPECT_EQ(split_face_refusal(tet, Face(99)), refusal_text(Refusal::face_not_live));
  EXPECT_EQ(cut_face_refusal(tet, Halfedge(0), Halfedge(0)), refusal_text(Refusal::cut_same_halfedge));
  EXPECT_EQ(remove_vertex_refusal(tet, Vertex(99)), refusal_text(Refusal::vertex_not_live));
  const Vertex two[] = {Vertex(0), Vertex(1)};
  EXPECT_EQ(add_face_refusal(tet, two), refusal_text(Refusal::add_face_too_few_corners));
  EXPECT_EQ(fill_hole_refusal(tet, Halfedge(0)), refusal_text(Refusal::fill_hole_not_boundary));
  EXPECT_EQ(refusal_code(flip_refusal(square, open)), Refusal::flip_boundary_edge);
  EXPECT_TRUE(tet.validate().empty());
  EXPECT_TRUE(square.validate().empty());
}

}  // namespace
}  // namespace hedge
