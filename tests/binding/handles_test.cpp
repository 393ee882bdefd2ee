// Element handles checked by the binding core (src/binding/handles.cpp).
#include "binding/handles.h"

#include <gtest/gtest.h>

#include <string>

#include "binding/errors.h"
#include "binding_error.h"
#include "hedge/core/build.h"
#include "hedge/core/face_operations.h"
#include "test_meshes.h"

namespace hedge::binding {
namespace {

// The message of the BindingError that body() throws, which must be HEDGE_ERROR_BAD_HANDLE.
template <typename Body>
std::string bad_handle(Body&& body) {
  const BindingError e = error_of(body);
  EXPECT_EQ(e.status, HEDGE_ERROR_BAD_HANDLE);
  return e.message;
}

TEST(BindingHandles, LiveElementsPassAndOthersSayWhy) {
  SurfaceMesh m = build(test::tetrahedron());
  EXPECT_EQ(live_vertex(m, 3), Vertex(3));
  EXPECT_EQ(live_halfedge(m, 11), Halfedge(11));
  EXPECT_EQ(live_element<Edge>(m, 5), Edge(5));
  EXPECT_EQ(live_element<Face>(m, 0), Face(0));
  EXPECT_EQ(bad_handle([&] { live_edge(m, 6); }), "edge 6 is out of range (the mesh has 6 edge slots)");
  EXPECT_EQ(bad_handle([&] { live_face(m, kInvalidIndex); }),
            "face is the invalid index (HEDGE_INVALID_INDEX, -1)");
  ASSERT_TRUE(remove_face(m, Face(0)));
  EXPECT_EQ(bad_handle([&] { live_face(m, 0); }), "face 0 is deleted");
  EXPECT_STREQ(element_kind<Halfedge>(), "halfedge");
  EXPECT_EQ(element_name("vertex", 7), "vertex 7");
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge::binding
