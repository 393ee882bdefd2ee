// The refusable edits as the bindings do them (src/binding/edits.cpp).
#include "binding/edits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "binding/errors.h"
#include "binding_error.h"
#include "hedge/core/build.h"
#include "hedge/core/operations.h"
#include "test_meshes.h"

namespace hedge::binding {
namespace {

TEST(BindingEdits, ARefusedEditSaysWhatAndWhyAndChangesNothing) {
  SurfaceMesh m = build(test::grid(2, true));
  const Edge boundary = m.find_edge(Vertex(0), Vertex(1));
  const std::uint32_t e = boundary.idx();
  const BindingError r = error_of([&] { flip(m, e); });
  EXPECT_EQ(r.status, HEDGE_ERROR_REFUSED);
  EXPECT_STREQ(r.refusal, flip_refusal(m, boundary));
  EXPECT_EQ(r.message, "flip of edge " + std::to_string(e) + " refused: " + flip_refusal(m, boundary) +
                           "; nothing was changed");
  EXPECT_EQ(error_of([&] { collapse(m, 999); }).status, HEDGE_ERROR_BAD_HANDLE);
  EXPECT_EQ(error_of([&] {
              split_edge(m, e, Vec3{NAN, 0, 0});
            }).message,
            "split_edge: point (nan, 0, 0) is not finite");
  EXPECT_EQ(m.n_faces(), 8u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(BindingEdits, AllowedEditsAreDone) {
  SurfaceMesh m = build(test::grid(3, false));  // 3 x 3 quads; vertex j * 4 + i
  const Vertex mid = split_edge(m, m.find_edge(Vertex(0), Vertex(1)).idx(), std::nullopt);
  EXPECT_EQ(m.position(mid), (Vec3{0.5f, 0, 0}));
  const Halfedge h0 = m.halfedge(Face(8));
  EXPECT_TRUE(m.is_live(cut_face(m, h0.idx(), m.next(m.next(h0)).idx())));
  EXPECT_TRUE(m.is_live(split_face(m, 0, std::nullopt)));
  remove_face(m, 4);                                            // the centre: a hole of 4 edges
  const Halfedge hole = m.find_halfedge(Vertex(5), Vertex(6));  // its side, now boundary
  ASSERT_TRUE(m.is_boundary(hole));
  EXPECT_EQ(fill_hole(m, hole.idx()).size(), 2u);
  remove_vertex(m, 15);  // a corner with its quad
  EXPECT_FALSE(m.is_live(Vertex(15)));
  EXPECT_TRUE(m.validate().empty());
}

TEST(BindingEdits, RefusalByNameAndArity) {
  SurfaceMesh m = build(test::grid(1, false));
  EXPECT_EQ(parse_edit("cutFace", EditNaming::camel_case), Edit::cut_face);
  EXPECT_EQ(parse_edit("fill_hole", EditNaming::snake_case), Edit::fill_hole);
  EXPECT_EQ(parse_edit("remove_face", EditNaming::snake_case), Edit::remove_face);
  // Each caller's spelling only: the error lists the edits as that caller names them.
  EXPECT_EQ(error_of([] { parse_edit("explode", EditNaming::camel_case); }).message,
            "unknown edit 'explode' (splitEdge, collapse, flip, splitFace, cutFace, fillHole)");
  EXPECT_EQ(
      error_of([] { parse_edit("cutFace", EditNaming::snake_case); }).message,
      "unknown edit 'cutFace' (split_edge, collapse, flip, split_face, cut_face, fill_hole, remove_face)");
  EXPECT_EQ(parse_edit("split_edge", EditNaming::camel_case), Edit::split_edge);  // as the JS API always took
  EXPECT_EQ(error_of([] { parse_edit("removeFace", EditNaming::camel_case); }).status,
            HEDGE_ERROR_INVALID_ARGUMENT);
  const std::uint32_t one[] = {0}, two[] = {0, 0};
  EXPECT_STREQ(refusal(m, Edit::cut_face, two), "the two half-edges are the same");
  EXPECT_STREQ(refusal(m, Edit::split_face, std::vector<std::uint32_t>{7}), "the face is not live");
  EXPECT_EQ(refusal(m, Edit::split_face, one), nullptr);
  EXPECT_STREQ(refusal(m, Edit::remove_face, std::vector<std::uint32_t>{0xffffffffu}),
               "the face is not live");
  EXPECT_EQ(refusal(m, Edit::remove_face, one), nullptr);
  EXPECT_EQ(error_of([&] { refusal(m, Edit::flip, two); }).status, HEDGE_ERROR_INVALID_ARGUMENT);
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge::binding
