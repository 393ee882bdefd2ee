#include "picture/shaded.h"

#include <gtest/gtest.h>

#include "hedge/error.h"
#include "picture/picture_test_util.h"

namespace hedge::picture {
namespace {

using test::mesh_of;

SurfaceMesh tetrahedron() {
  return mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3});
}

TEST(ShadedPicture, AViewFramesTheMeshAsFrameAndRenderDo) {
  const SurfaceMesh mesh = tetrahedron();
  ShadedOptions s;
  s.width = 64;
  s.height = 48;
  s.view = View::front;
  s.color_by = ColorBy::face;
  s.wireframe = true;
  s.feature_angle = 30;
  RenderOptions r;
  r.width = 64;
  r.height = 48;
  r.color_by = ColorBy::face;
  r.wireframe = true;
  r.feature_angle = 30;
  const Image expected = render(mesh, frame(mesh, View::front, 64.0 / 48), r);
  EXPECT_EQ(shaded_picture(mesh, s).pixels(), expected.pixels());
  s.view = View::top;
  EXPECT_NE(shaded_picture(mesh, s).pixels(), expected.pixels());
}

TEST(ShadedPicture, AnExplicitCameraWinsOverTheView) {
  const SurfaceMesh mesh = tetrahedron();
  ShadedOptions s;
  s.width = s.height = 40;
  s.camera = test::ortho_camera();
  RenderOptions r;
  r.width = r.height = 40;
  r.feature_angle = 60;
  EXPECT_EQ(shaded_picture(mesh, s).pixels(), render(mesh, test::ortho_camera(), r).pixels());
}

TEST(ShadedPicture, NamesParseAndBadOnesListTheValidOnes) {
  EXPECT_EQ(shading_named("flat"), Shading::flat);
  EXPECT_EQ(color_by_named("valence"), ColorBy::valence);
  EXPECT_EQ(view_named("top"), View::top);
  EXPECT_THROW(shading_named("unlit"), InvalidInputError);  // for diagrams, not a picture option
  try {
    color_by_named("colour");
    FAIL();
  } catch (const InvalidInputError& e) {
    EXPECT_STREQ(e.what(), "color_by 'colour' is not one of none, face, shard, curvature, valence");
  }
  EXPECT_THROW(view_named("side"), InvalidInputError);
}

TEST(ShadedPicture, BadSizesAndEmptyMeshesAreRefused) {
  ShadedOptions s;
  s.width = 0;
  EXPECT_THROW(shaded_picture(tetrahedron(), s), InvalidInputError);
  s.width = 10;
  SurfaceMesh empty;
  EXPECT_THROW(shaded_picture(empty, s), InvalidInputError);
}

TEST(ShadedPicture, BytesCountSamplesAndThePicture) {
  EXPECT_DOUBLE_EQ(shaded_picture_bytes(10, 20, 2), 10.0 * 20 * 4 * (sizeof(float) + 3) + 3.0 * 10 * 20);
}

}  // namespace
}  // namespace hedge::picture
