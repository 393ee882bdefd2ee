// A face added with texcoords per corner and a submesh (src/binding/face_attributes.cpp).
#include "binding/face_attributes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "binding/edits.h"
#include "binding_error.h"
#include "hedge/core/build.h"
#include "hedge/core/operations.h"
#include "test_meshes.h"

namespace hedge::binding {
namespace {

// A 2 x 2 grid of triangles with its face 0 removed: the corners it had, to add back.
struct Opened {
  SurfaceMesh mesh = build(test::grid(2, true));
  std::vector<Vertex> corners;
  Opened() {
    for (const Vertex v : mesh.vertices(Face(0))) corners.push_back(v);
    remove_face(mesh, 0);
  }
};

TEST(FaceAttributes, TexcoordsGoToTheCornersAndTheSubmeshToTheFace) {
  Opened o;
  const Vec2 uv[] = {{0.1f, 0.2f}, {0.3f, 0.4f}, {0.5f, 0.6f}};
  const Face f = add_face(o.mesh, o.corners, {uv, 7});
  const auto texcoord = o.mesh.get_halfedge_property<Vec2>("h:texcoord");
  ASSERT_TRUE(texcoord);
  int seen = 0;
  for (const Halfedge h : o.mesh.halfedges(f))
    for (std::size_t i = 0; i < 3; ++i)
      if (o.mesh.to_vertex(h) == o.corners[i]) {
        EXPECT_EQ(texcoord[h], uv[i]) << "corner " << i;
        ++seen;
      }
  EXPECT_EQ(seen, 3);
  const auto submesh = o.mesh.get_face_property<std::int32_t>("f:submesh");
  ASSERT_TRUE(submesh);
  EXPECT_EQ(submesh[f], 7);
  EXPECT_EQ(submesh[Face(1)], 0) << "the other faces: the default";
  EXPECT_EQ(texcoord[o.mesh.halfedge(Face(1))], (Vec2{0, 0}));
  EXPECT_TRUE(o.mesh.validate().empty());
}

TEST(FaceAttributes, NoneGivenAddsNoProperty) {
  Opened o;
  const Face f = add_face(o.mesh, o.corners, {});
  EXPECT_TRUE(o.mesh.is_live(f));
  EXPECT_FALSE(o.mesh.get_halfedge_property<Vec2>("h:texcoord"));
  EXPECT_FALSE(o.mesh.get_face_property<std::int32_t>("f:submesh"));
  EXPECT_TRUE(o.mesh.validate().empty());
}

// Bad attributes fail before the mesh changes, saying which and why; a refused face adds no property.
TEST(FaceAttributes, BadAttributesAndRefusalsChangeNothing) {
  Opened o;
  const std::size_t faces = o.mesh.n_faces();
  const Vec2 two[] = {{0, 0}, {1, 1}};
  const Vec2 nan[] = {{0, 0}, {NAN, 0}, {1, 1}};
  const Vec2 three[] = {{0, 0}, {1, 0}, {1, 1}};
  BindingError e = error_of([&] { add_face(o.mesh, o.corners, {two, std::nullopt}); });
  EXPECT_EQ(e.status, HEDGE_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(e.message, "add_face: 2 texcoords for 3 corners");
  EXPECT_EQ(error_of([&] {
              add_face(o.mesh, o.corners, {nan, std::nullopt});
            }).message,
            "add_face: texcoord 1 is not finite");
  EXPECT_EQ(error_of([&] {
              add_face(o.mesh, o.corners, {{}, 65536});
            }).message,
            "add_face: submesh 65536 is not in [0, 65535]");
  EXPECT_EQ(error_of([&] { add_face(o.mesh, o.corners, {{}, -2}); }).status, HEDGE_ERROR_INVALID_ARGUMENT);
  const std::vector<Vertex> taken = {o.corners[2], o.corners[1], o.corners[0]};  // reversed: a closed side
  e = error_of([&] { add_face(o.mesh, taken, {three, 1}); });
  EXPECT_EQ(e.status, HEDGE_ERROR_REFUSED);
  o.mesh.add_face_property<float>("f:submesh");
  EXPECT_EQ(error_of([&] {
              add_face(o.mesh, o.corners, {{}, 1});
            }).message,
            "the mesh's \"f:submesh\" is not of type int32, as add_face's attributes need");
  EXPECT_EQ(o.mesh.n_faces(), faces);
  EXPECT_FALSE(o.mesh.get_halfedge_property<Vec2>("h:texcoord")) << "nothing was added";
  EXPECT_TRUE(o.mesh.validate().empty());
}

TEST(FaceAttributes, PerVertexTexcoordsTakeNoCornerTexcoords) {
  Opened o;
  o.mesh.add_vertex_property<Vec2>("v:texcoord");
  const Vec2 three[] = {{0, 0}, {1, 0}, {1, 1}};
  EXPECT_EQ(
      error_of([&] {
        add_face(o.mesh, o.corners, {three, std::nullopt});
      }).message,
      "add_face: the mesh keeps its texcoords per vertex (\"v:texcoord\"), not per corner (\"h:texcoord\")");
  EXPECT_TRUE(o.mesh.is_live(add_face(o.mesh, o.corners, {{}, 2})));
  EXPECT_TRUE(o.mesh.validate().empty());
}

}  // namespace
}  // namespace hedge::binding
