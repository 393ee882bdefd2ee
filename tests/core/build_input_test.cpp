// build(), first step (src/core/build_input.cpp): input errors, welding, degenerate faces.
#include <gtest/gtest.h>

#include <cstddef>
#include <limits>
#include <string>

#include "core/build_test_util.h"
#include "hedge/core/build.h"
#include "hedge/error.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using test::repair;
using test::tetrahedron;

// build(in, options) throws an InvalidInputError whose message holds `what`.
void expect_input_error(const IndexedMesh& in, const BuildOptions& options, const std::string& what) {
  try {
    build(in, options);
    ADD_FAILURE() << "expected InvalidInputError";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

TEST(Build, BadIndicesAndCoordinatesAreInputErrors) {
  IndexedMesh in = tetrahedron();
  in.indices[4] = 9;
  expect_input_error(in, {}, "corner 4 refers to vertex 9");
  in = tetrahedron();
  in.positions[2].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(build(in, repair()), InvalidInputError);
  in = tetrahedron();
  in.indices.pop_back();
  EXPECT_THROW(build(in), InvalidInputError);
  in = test::cube();
  in.face_sizes[0] = 5;
  EXPECT_THROW(build(in), InvalidInputError);
}

TEST(Build, CornerAttributeIndicesAreInputErrors) {
  IndexedMesh in = tetrahedron();
  in.texcoords = {{0, 0}, {1, 0}};
  in.texcoord_indices.assign(in.indices.size() - 1, 0);  // one index short
  EXPECT_THROW(build(in), InvalidInputError);
  in.texcoord_indices.assign(in.indices.size(), 0);
  in.texcoord_indices[5] = 2;  // past the end of the pool
  expect_input_error(in, {}, "corner 5 refers to texcoord 2");
  in.texcoord_indices[5] = 1;
  in.normals = {{0, 0, 1}};
  in.normal_indices.assign(in.indices.size(), 1);
  EXPECT_THROW(build(in, repair()), InvalidInputError);  // not a topology defect to repair
  in.normal_indices.assign(in.indices.size(), 0);
  SurfaceMesh m = build(in);
  EXPECT_TRUE(m.get_halfedge_property<Vec2>("h:texcoord"));
  EXPECT_TRUE(m.get_halfedge_property<Vec3>("h:normal"));
  EXPECT_TRUE(m.validate().empty());
}

TEST(Build, ColourIndicesAndNonFiniteColoursAreInputErrors) {
  IndexedMesh in = tetrahedron();
  in.colors = {{1, 0, 0, 1}, {0, 1, 0, 1}};
  in.color_indices.assign(in.indices.size(), 0);
  in.color_indices[7] = 2;  // past the end of the pool
  expect_input_error(in, {}, "corner 7 refers to color 2");
  in.color_indices[7] = 1;
  in.colors[1].a = std::numeric_limits<float>::infinity();
  expect_input_error(in, repair(), "color 1 has a non-finite component");
  in.colors[1].a = 1;
  SurfaceMesh m = build(in);
  EXPECT_TRUE(m.get_halfedge_property<Color>("h:color"));
  EXPECT_TRUE(m.validate().empty());
}

TEST(Build, RepairDropsOnlyDegenerateFaces) {
  IndexedMesh in = test::grid(2, false);
  in.indices.insert(in.indices.end(), {0, 1, 0});  // repeated vertex: dropped
  in.face_sizes.push_back(3);
  in.indices.insert(in.indices.end(), {0, 1});  // two corners: dropped
  in.face_sizes.push_back(2);
  in.indices.insert(in.indices.end(), {9, 10, 10, 11, 9});  // consecutive repeats: kept as a triangle
  in.face_sizes.push_back(5);
  in.positions.push_back({3, 0, 0});
  in.positions.push_back({4, 0, 0});
  in.positions.push_back({4, 1, 0});
  BuildReport rep;
  SurfaceMesh m = build(in, repair(), &rep);
  EXPECT_EQ(rep.degenerate_faces, 2u);
  EXPECT_EQ(rep.repeated_corners, 2u);
  EXPECT_EQ(m.n_faces(), 5u);
  EXPECT_EQ(rep.face_map[4], kInvalidIndex);
  EXPECT_EQ(rep.face_map[5], kInvalidIndex);
  EXPECT_EQ(rep.face_map[6], 4u);
  EXPECT_EQ(m.valence(Face(4)), 3u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Build, ExactWeldingOfTriangleSoup) {
  IndexedMesh soup;
  IndexedMesh tet = tetrahedron();
  for (Index i : tet.indices) {
    soup.indices.push_back(static_cast<Index>(soup.positions.size()));
    soup.positions.push_back(tet.positions[i]);
  }
  soup.positions[0].x = -0.0f;  // -0 and +0 weld
  BuildOptions o;
  o.weld = Weld::exact;
  BuildReport rep;
  SurfaceMesh m = build(soup, o, &rep);
  EXPECT_EQ(m.n_vertices(), 4u);
  EXPECT_EQ(rep.welded_vertices, 8u);
  EXPECT_EQ(rep.vertex_map.size(), 12u);
  EXPECT_EQ(m.boundary_loops().size(), 0u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Build, EpsilonWeldingMergesFloatNoiseOnly) {
  IndexedMesh in = test::grid(2, true);
  // Duplicate vertex 4 (the centre) with noise and rewire the upper-right triangles to it.
  in.positions.push_back(in.positions[4] + Vec3{1e-7f, -1e-7f, 0});
  for (std::size_t c = 12; c < in.indices.size(); ++c)
    if (in.indices[c] == 4) in.indices[c] = 9;
  BuildOptions o = repair();
  o.weld = Weld::exact;
  // Exact welding cannot see it: the slit pinches vertices 3 and 5, which repair splits.
  EXPECT_EQ(build(in, o).n_vertices(), 12u);
  o.weld = Weld::epsilon;
  o.weld_epsilon = 1e-6;
  BuildReport rep;
  SurfaceMesh m = build(in, o, &rep);
  EXPECT_EQ(m.n_vertices(), 9u);
  EXPECT_EQ(rep.vertex_map[9], 4u);
  EXPECT_EQ(m.boundary_loops().size(), 1u);
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge
