// A computed solid fracture strike applied (fracture_solid_apply.cpp): the pieces get their
// properties, the remaining object its patch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "algorithms/fracture_solid_strike.h"
#include "fracture_solid_checks.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/locate.h"
#include "hedge/algorithms/normals.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/core/build.h"
#include "hedge/core/threads.h"
#include "hedge/io/io.h"
#include "test_meshes.h"

namespace hedge::solid_detail {
namespace {

struct Setting {
  FaceBvh tree;
  SolidFractureOptions options;
  StrikeInput in;
  Setting(SurfaceMesh& mesh, const Vec3d& centre, double radius)
      : tree(mesh),
        options{.material = fracture_material("stone"), .radius = radius},
        in{mesh, tree, centre, 0, fracture_material_at_radius(options.material, radius), options} {
    in.region_radius = radius + 0.5 * in.material.rings.back().spacing;
  }
};

SurfaceMesh quad_sphere() {
  SurfaceMesh m = build(test::cube());
  subdivide(m, Subdivision::catmull_clark, 3);
  return m;
}

TEST(FractureSolidApply, PiecesKeepTheirSourceFacesPropertiesAndCapsAreMarked) {
  SurfaceMesh m = quad_sphere();
  FaceProperty<std::int32_t> id = m.face_property<std::int32_t>("f:id", -1);
  for (Face f : m.faces()) id[f] = static_cast<std::int32_t>(f.idx());
  Setting s(m, to_double(m.position(Vertex(3))), 0.3);
  std::vector<Face> faces;
  region_faces(s.in, faces);
  Strike strike;
  ASSERT_TRUE(compute_strike(s.in, faces, 0.0, 11, strike)) << strike.failure;
  std::vector<std::vector<std::uint32_t>> sources;
  for (const PieceDraft& d : strike.pieces) sources.push_back(d.surface.source);
  const std::vector<SolidPiece> pieces = assemble_pieces(s.in, strike, 7);
  ASSERT_EQ(pieces.size(), sources.size());
  std::size_t caps = 0, outer = 0;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const SurfaceMesh& out = pieces[p].mesh;
    const auto piece_id = out.get_face_property<std::int32_t>("f:id");
    const auto inner = out.get_face_property<std::uint8_t>(kInnerProperty);
    const auto submesh = out.get_face_property<std::int32_t>(kSubmeshProperty);
    ASSERT_TRUE(piece_id && inner && submesh);
    ASSERT_EQ(out.n_faces(), sources[p].size());
    for (Face f : out.faces()) {
      const std::uint32_t from = sources[p][f.idx()];
      if (from & kCapBit) {
        ++caps;
        EXPECT_EQ(inner[f], 1);
        EXPECT_EQ(submesh[f], 7);
        EXPECT_EQ(piece_id[f], -1);  // no source face: the property's default
      } else {
        ++outer;
        EXPECT_EQ(inner[f], 0);
        EXPECT_EQ(piece_id[f], static_cast<std::int32_t>(strike.soup[from].face.idx()));
      }
    }
    EXPECT_TRUE(out.validate().empty());
  }
  EXPECT_GT(caps, 0u);
  EXPECT_GT(outer, 0u);
}

TEST(FractureSolidApply, PiecesAreMeasuredAlikeOnOneThreadOrSeveral) {
  SurfaceMesh m = quad_sphere();
  Setting s(m, to_double(m.position(Vertex(3))), 0.4);
  s.options.hulls = true;
  s.in.material = fracture_material_at_radius(fracture_material("glass"), 0.4);  // more pieces
  s.in.region_radius = 0.4 + 0.5 * s.in.material.rings.back().spacing;
  std::vector<Face> faces;
  region_faces(s.in, faces);
  Strike strike;
  ASSERT_TRUE(compute_strike(s.in, faces, 0.0, 5, strike)) << strike.failure;
  std::vector<SolidPiece> one = assemble_pieces(s.in, strike, 1);
  ASSERT_GE(one.size(), 8u);  // enough for two threads of kPiecesPerThread
  std::vector<SolidPiece> several = one;
  set_max_threads(1);
  measure_pieces(one, s.options);
  set_max_threads(4);
  measure_pieces(several, s.options);
  set_max_threads(0);
  for (std::size_t p = 0; p < one.size(); ++p) {
    // Each piece's own: its volume and hull, the same bit for bit whatever the threads.
    EXPECT_GT(one[p].volume, 0);
    EXPECT_NEAR(one[p].volume, volume(one[p].mesh), 1e-9);
    EXPECT_EQ(one[p].volume, several[p].volume);
    EXPECT_EQ(one[p].mass.mass, several[p].mass.mass);
    EXPECT_EQ(one[p].centroid, several[p].centroid);
    EXPECT_EQ(one[p].hull.mesh.n_faces(), several[p].hull.mesh.n_faces());
    EXPECT_GT(several[p].hull.mesh.n_faces(), 0u);
    EXPECT_TRUE(several[p].hull.mesh.validate().empty());
    EXPECT_TRUE(several[p].mesh.validate().empty());
  }
}

// The remaining object is edited beside the measuring of the pieces: the edit runs once, the
// pieces come out as measured alone, on one thread or two, and what the edit throws is passed on.
TEST(FractureSolidApply, PiecesAreMeasuredBesideTheEdit) {
  for (const unsigned threads : {1u, 2u}) {
    SCOPED_TRACE(testing::Message() << threads << " thread(s)");
    SurfaceMesh m = quad_sphere();
    Setting s(m, to_double(m.position(Vertex(3))), 0.4);
    s.options.hulls = true;
    std::vector<Face> faces;
    region_faces(s.in, faces);
    Strike strike;
    ASSERT_TRUE(compute_strike(s.in, faces, 0.0, 5, strike)) << strike.failure;
    std::vector<SolidPiece> pieces = assemble_pieces(s.in, strike, 1);
    ASSERT_GE(pieces.size(), 4u);
    std::vector<SolidPiece> alone = pieces;
    set_max_threads(1);
    measure_pieces(alone, s.options);
    set_max_threads(threads);
    int edits = 0;
    measure_pieces(pieces, s.options, [&] {
      ++edits;
      apply_remaining(s.in, strike, 1);
    });
    std::vector<SolidPiece> failed = alone;
    EXPECT_THROW(measure_pieces(failed, s.options, [] { throw std::runtime_error("edit failed"); }),
                 std::runtime_error);
    set_max_threads(0);
    EXPECT_EQ(edits, 1);
    EXPECT_EQ(solid_test::solid_problem(m), "");
    EXPECT_TRUE(m.validate().empty());
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      EXPECT_EQ(pieces[p].volume, alone[p].volume);
      EXPECT_EQ(pieces[p].centroid, alone[p].centroid);
      EXPECT_EQ(pieces[p].hull.mesh.n_faces(), alone[p].hull.mesh.n_faces());
      EXPECT_TRUE(pieces[p].mesh.validate().empty());
    }
  }
}

TEST(FractureSolidApply, TheRemainingObjectGetsThePatchInPlaceOfTheTouchedFaces) {
  SurfaceMesh m = quad_sphere();
  const double before = volume(m);
  const std::size_t faces_before = m.n_faces();
  Setting s(m, to_double(m.position(Vertex(3))), 0.3);
  std::vector<Face> faces;
  region_faces(s.in, faces);
  Strike strike;
  ASSERT_TRUE(compute_strike(s.in, faces, 0.0, 11, strike)) << strike.failure;
  const std::size_t touched = strike.touched.size(), patch = strike.patch.tris.size();
  std::vector<SolidPiece> pieces = assemble_pieces(s.in, strike, 1);
  apply_remaining(s.in, strike, 1);
  EXPECT_EQ(m.n_faces(), faces_before - touched + patch);
  EXPECT_EQ(solid_test::solid_problem(m), "");
  double total = volume(m);
  for (const SolidPiece& p : pieces) total += volume(p.mesh);
  EXPECT_NEAR(total, before, 1e-6 * before);
  const auto inner = m.get_face_property<std::uint8_t>(kInnerProperty);
  ASSERT_TRUE(inner);
  std::size_t caps = 0;
  for (Face f : m.faces()) caps += inner[f];
  EXPECT_GT(caps, 0u);
  measure_pieces(pieces, s.options);
  for (const SolidPiece& p : pieces) {
    EXPECT_NEAR(p.volume, volume(p.mesh), 1e-9 * before);
    EXPECT_GT(p.mass.mass, 0);
    EXPECT_GE(p.hull.mesh.n_faces(), 4u);
  }
}

//! Every corner normal of `m` is unit length (or zero where the input had none); on cap faces it
//! is the face's normal (flat, as a cut is). Returns the number of cap corners seen.
std::size_t expect_cap_normals(const SurfaceMesh& m, const std::string& what) {
  const auto normal = m.get_halfedge_property<Vec3>("h:normal");
  const auto inner = m.get_face_property<std::uint8_t>(kInnerProperty);
  EXPECT_TRUE(normal && inner) << what;
  if (!normal || !inner) return 0;
  std::size_t seen = 0;
  for (Face f : m.faces()) {
    const Vec3d n = to_double(face_normal(m, f));
    for (Halfedge h : m.halfedges(f)) {
      const Vec3d c = to_double(normal[h]);
      EXPECT_NEAR(norm(c), 1, 1e-5) << what << ", face " << f.idx();
      if (!inner[f]) continue;
      ++seen;
      // Float positions of a sliver give its normal to a few 1e-4 at worst.
      if (face_area(m, f) > 1e-8) EXPECT_GT(dot(c, n), 1 - 1e-4) << what << ", cap face " << f.idx();
    }
  }
  return seen;
}

TEST(FractureSolidApply, CapCornersCarryThePlanesNormalOutOfThePiece) {
  SurfaceMesh m = read_mesh(test::data_path("bob_small.ply"));
  compute_corner_normals(m, 180);
  const double before = volume(m);
  const SolidFractureResult r = fracture_solid(m, m.position(Vertex(10)), {.seed = 4});
  ASSERT_GT(r.pieces.size(), 1u);
  solid_test::expect_solid_strike(m, r, before);
  std::size_t caps = 0;
  for (std::size_t i = 0; i < r.pieces.size(); ++i)
    caps += expect_cap_normals(r.pieces[i].mesh, "piece " + std::to_string(i));
  EXPECT_GT(caps, 0u);
  EXPECT_GT(expect_cap_normals(m, "the remaining object"), 0u);
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge::solid_detail
