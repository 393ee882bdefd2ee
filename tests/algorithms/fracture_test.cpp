#include "hedge/algorithms/fracture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "caught.h"
#include "edit_checks.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/core/build.h"
#include "hedge/core/export.h"
#include "hedge/core/face_operations.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "non_finite.h"
#include "test_meshes.h"

namespace hedge {
namespace {

// A deterministic generator for the test's own choices (impacts), independent of the library's.
struct TestRng {
  std::uint64_t s;
  std::uint64_t next() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return s >> 11;
  }
  double uniform() { return double(next() >> 11) * 0x1.0p-42; }
};

bool has_boundary(const SurfaceMesh& m) {
  for (Halfedge h : m.halfedges())
    if (m.is_boundary(h)) return true;
  return false;
}

// Hulls that reported a point outside beyond their tolerance (max_outside_distance), and all.
std::size_t g_hulls_outside = 0, g_hulls = 0;

// Each vertex of the shard lies inside every hull face's plane, within the hull's tolerance plus
// what it reports as outside, which must be tiny.
void expect_hull_contains(const Shard& s) {
  if (s.hull.mesh.n_faces() == 0) return;
  const BoundingBox box = bounding_box(s.mesh);
  const double size = norm(to_double(box.max - box.min));
  ++g_hulls;
  if (s.hull.max_outside_distance > 0) ++g_hulls_outside;
  EXPECT_EQ(s.hull.max_outside_distance, 0);
  const double slack = s.hull.tolerance + 1e-6 * size;
  for (Face f : s.hull.mesh.faces()) {
    const Vec3d n = normalize(area_vector(s.hull.mesh, f));
    const Vec3d a = to_double(s.hull.mesh.position(s.hull.mesh.to_vertex(s.hull.mesh.halfedge(f))));
    for (Vertex v : s.mesh.vertices())
      ASSERT_LE(dot(to_double(s.mesh.position(v)) - a, n), slack)
          << "hull of " << s.mesh.n_vertices() << " points, dimension " << int(s.hull.dimension)
          << ", thickness " << s.hull.thickness << ", outside " << s.hull.max_outside_distance
          << ", tolerance " << s.hull.tolerance << ", points " << [&] {
               std::string list;
               char buf[96];
               for (Vertex w : s.mesh.vertices()) {
                 const Vec3 q = s.mesh.position(w);
                 std::snprintf(buf, sizeof buf, "{%.9g, %.9g, %.9g}, ", q.x, q.y, q.z);
                 list += buf;
               }
               return list;
             }();
  }
}

// The checks every fracture must pass, given the area before.
void expect_sound(const SurfaceMesh& mesh, const FractureResult& r, double area_before, double thickness) {
  EXPECT_TRUE(mesh.validate().empty());
  double total = surface_area(mesh);
  for (const Shard& s : r.shards) {
    ASSERT_TRUE(s.mesh.validate().empty());
    ASSERT_GT(s.mesh.n_faces(), 0u);
    total += s.area;
    if (thickness > 0) {
      EXPECT_TRUE(s.closed);
      EXPECT_FALSE(has_boundary(s.mesh));
      EXPECT_GT(s.mass.volume, 0);
      EXPECT_GT(s.mass.mass, 0);
    } else {
      EXPECT_EQ(s.closed, !has_boundary(s.mesh));
    }
    if (!s.closed) {  // a thin shell's mass properties, ready for a physics engine
      EXPECT_GT(s.shell_thickness, 0);
      EXPECT_NEAR(s.mass.volume, s.area * s.shell_thickness, 1e-9 * s.mass.volume);
      EXPECT_GT(s.mass.principal_moments.x, 0);  // the smallest: positive definite
    }
    expect_hull_contains(s);
  }
  EXPECT_NEAR(total, area_before, 1e-5 * area_before);
}

double diagonal(const SurfaceMesh& m) { return norm(to_double(bounding_box(m).size())); }

SurfaceMesh plate(int n) { return build(test::grid(n, true)); }

TEST(Fracture, GlassBreaksAPlateIntoManyShardsOfSeveralFaces) {
  SurfaceMesh mesh = plate(60);
  const double area = surface_area(mesh);
  FractureOptions o;
  o.seed = 7;
  const FractureResult r = fracture(mesh, {30.3f, 29.6f, 0}, o);
  expect_sound(mesh, r, area, 0);
  EXPECT_GE(r.shards.size(), 30u);
  EXPECT_LE(r.shards.size(), 60u);
  std::size_t faces = 0;
  for (const Shard& s : r.shards) faces += s.mesh.n_faces();
  EXPECT_GE(double(faces) / double(r.shards.size()), 3.0);  // cells, not single triangles
  // The broken area is local: far corners of the plate keep their faces.
  EXPECT_GT(mesh.n_faces(), 60u * 60u * 2u - faces);
  EXPECT_LT(std::abs(r.impact_point.x - 30.3f), 1e-5f);
  // The break radius is glass's fraction of the plate's diagonal; the area reaches half the outer
  // spacing (2.4 of 7) farther.
  EXPECT_NEAR(r.break_radius, 0.13 * diagonal(mesh), 1e-4);
  for (const Shard& s : r.shards) {
    EXPECT_LT(std::hypot(s.centroid.x - 30.3, s.centroid.y - 29.6), r.break_radius * (1 + 1.2 / 7));
    EXPECT_NEAR(s.centroid.z, 0, 1e-9);
  }
  EXPECT_TRUE(mesh.validate().empty());
}

TEST(Fracture, ThicknessMakesClosedSolidsWithMass) {
  SurfaceMesh mesh = plate(50);
  const double area = surface_area(mesh);
  FractureOptions o;
  o.thickness = 0.2;
  o.density = 2.5;
  o.seed = 5;
  const FractureResult r = fracture(mesh, {25.1f, 24.7f, 0}, o);
  expect_sound(mesh, r, area, o.thickness);
  for (const Shard& s : r.shards) {
    // A flat plate extruded: the volume is area x thickness.
    EXPECT_NEAR(s.mass.volume, s.area * 0.2, 1e-4 * s.area);
    EXPECT_NEAR(s.mass.mass, s.mass.volume * 2.5, 1e-6 * s.mass.mass);
    EXPECT_NEAR(s.mass.centre_of_mass.z, -0.1, 1e-4);
    EXPECT_EQ(s.hull.dimension, HullDimension::solid);
  }
}

// With a thickness, the back copy and the side walls are new cut faces: they get an "f:submesh" of
// their own (one past the mesh's largest by default) while the broken faces keep theirs.
TEST(Fracture, InnerFacesOfASolidGetASubmeshOfTheirOwn) {
  struct Case {
    bool property;
    std::int32_t inner_option, inner_expected;
  };
  for (const Case c : {Case{true, -1, 3}, Case{true, 7, 7}, Case{false, -1, 1}}) {
    SurfaceMesh mesh = plate(30);
    if (c.property) {
      auto submesh = mesh.add_face_property<std::int32_t>("f:submesh", 0);
      for (Face f : mesh.faces()) submesh[f] = face_centroid(mesh, f).x < 15 ? 0 : 2;
    }
    FractureOptions o;
    o.seed = 4;
    o.thickness = 0.2;
    o.inner_submesh = c.inner_option;
    const FractureResult r = fracture(mesh, {15.2f, 14.9f, 0}, o);
    EXPECT_TRUE(mesh.validate().empty());
    ASSERT_FALSE(r.shards.empty());
    for (const Shard& s : r.shards) {
      ASSERT_TRUE(s.mesh.validate().empty());
      const auto submesh = s.mesh.get_face_property<std::int32_t>("f:submesh");
      ASSERT_TRUE(submesh);
      std::size_t inner = 0;
      for (Face f : s.mesh.faces()) {
        // The front lies at z = 0 with its normal up; the back and the walls lie below or across.
        const bool front = std::abs(face_centroid(s.mesh, f).z) < 1e-6 && area_vector(s.mesh, f).z > 0;
        if (front) {
          const std::int32_t expected = c.property && face_centroid(s.mesh, f).x >= 15 ? 2 : 0;
          if (std::abs(face_centroid(s.mesh, f).x - 15) > 0.5f) EXPECT_EQ(submesh[f], expected);
        } else {
          EXPECT_EQ(submesh[f], c.inner_expected);
          ++inner;
        }
      }
      EXPECT_GT(inner, s.mesh.n_faces() / 2);  // the back and the walls outnumber the front
    }
  }
  // Without a thickness nothing is added, so no "f:submesh" appears.
  SurfaceMesh open = plate(30);
  for (const Shard& s : fracture(open, {15.2f, 14.9f, 0}, {}).shards)
    EXPECT_FALSE(s.mesh.get_face_property<std::int32_t>("f:submesh"));
}

// A break radius far beyond the object: the whole 4 x 4 plate breaks off, and the relative thickness
// is a fraction of what broke (the plate's diagonal), not of the radius, so no solid is absurdly
// thick or heavy.
TEST(Fracture, RelativeThicknessIsBoundedByWhatBroke) {
  SurfaceMesh mesh = plate(4);
  const double area = surface_area(mesh);
  FractureOptions o;
  o.material = fracture_material_at_radius(fracture_material("stone"), 1000);
  o.relative_thickness = 0.05;
  const double thickness = 0.05 * std::sqrt(32.0);  // the plate's diagonal
  const FractureResult r = fracture(mesh, {2.1f, 1.9f, 0}, o);
  ASSERT_FALSE(r.shards.empty());
  expect_sound(mesh, r, area, thickness);
  double volume = 0;
  for (const Shard& s : r.shards) {
    EXPECT_NEAR(s.mass.volume, s.area * thickness, 1e-3 * s.area);
    volume += s.mass.volume;
  }
  EXPECT_NEAR(volume, area * thickness, 1e-3 * area);  // the whole plate, 0.28 thick (not 50)
}

// A thickness relative to the break radius: glass reaches 0.13 of the plate's diagonal.
TEST(Fracture, RelativeThicknessIsAFractionOfTheBreakRadius) {
  SurfaceMesh mesh = plate(50);
  const double area = surface_area(mesh);
  FractureOptions o;
  o.relative_thickness = 0.05;
  o.seed = 5;
  const double thickness = 0.05 * 0.13 * 50 * std::sqrt(2.0);
  const FractureResult r = fracture(mesh, {25.1f, 24.7f, 0}, o);
  expect_sound(mesh, r, area, thickness);
  for (const Shard& s : r.shards) EXPECT_NEAR(s.mass.volume, s.area * thickness, 1e-4 * s.area);
  // Both kinds of thickness, or a negative one: refused, naming them, the mesh unchanged.
  const test::Snapshot before = test::snapshot(mesh);
  o.thickness = 0.1;
  std::string what = test::caught<InvalidInputError>(
                         [&] {
                           fracture(mesh, {10.1f, 9.7f, 0}, o);
                         },
                         InvalidInputError(""))
                         .what();
  EXPECT_NE(what.find("relative_thickness (0.05) are both set"), std::string::npos) << what;
  o.thickness = 0;
  o.relative_thickness = -1;
  EXPECT_THROW(fracture(mesh, {10.1f, 9.7f, 0}, o), InvalidInputError);
  // A relative thickness beyond the break radius: refused, naming the limit.
  o.relative_thickness = 1.5;
  what = test::caught<InvalidInputError>(
             [&] {
               fracture(mesh, {10.1f, 9.7f, 0}, o);
             },
             InvalidInputError(""))
             .what();
  EXPECT_NE(what.find("kFractureMaxRelativeThickness"), std::string::npos) << what;
  o.relative_thickness = 0;
  o.inner_submesh = -2;
  EXPECT_THROW(fracture(mesh, {10.1f, 9.7f, 0}, o), InvalidInputError);
  EXPECT_TRUE(test::snapshot(mesh) == before);
  // An "f:submesh" of another type cannot take the inner faces' submesh: refused up front.
  mesh.add_face_property<float>("f:submesh", 0);
  o = {};
  o.thickness = 0.1;
  what = test::caught<InvalidInputError>(
             [&] {
               fracture(mesh, {10.1f, 9.7f, 0}, o);
             },
             InvalidInputError(""))
             .what();
  EXPECT_NE(what.find("not of type std::int32_t"), std::string::npos) << what;
  EXPECT_TRUE(mesh.validate().empty());
}

TEST(Fracture, SameSeedSameShardsBitForBitOtherSeedOtherShards) {
  auto run = [](std::uint64_t seed) {
    SurfaceMesh mesh = build(test::grid(40, true));
    FractureOptions o;
    o.seed = seed;
    o.thickness = 0.1;
    FractureResult r = fracture(mesh, {20.2f, 19.9f, 0}, o);
    std::vector<test::Snapshot> out;
    for (const Shard& s : r.shards) out.push_back(test::snapshot(s.mesh));
    out.push_back(test::snapshot(mesh));
    return out;
  };
  const auto a = run(42), b = run(42), c = run(43);
  EXPECT_TRUE(a == b);
  EXPECT_FALSE(a == c);
}

TEST(Fracture, ImpactOnAVertexAnEdgeAndTheBoundary) {
  for (const Vec3 impact : {Vec3{20, 20, 0}, Vec3{20.5f, 20, 0}, Vec3{20.5f, 20.5f, 0}, Vec3{0, 13.3f, 0},
                            Vec3{0, 0, 0}, Vec3{40, 40, 0}}) {
    SurfaceMesh mesh = plate(40);
    const double area = surface_area(mesh);
    const std::size_t vertices = mesh.n_vertices();
    FractureOptions o;
    o.seed = 1;
    const FractureResult r = fracture(mesh, impact, o);
    expect_sound(mesh, r, area, 0);
    EXPECT_GE(r.shards.size(), 10u);
    // On a vertex the impact is that vertex (no vertex added for it, no sliver).
    if (impact.x == 20 && impact.y == 20) {
      EXPECT_EQ(r.impact_point.x, 20.f);
    }
    for (const Shard& s : r.shards)
      for (Face f : s.mesh.faces()) EXPECT_GT(face_area(s.mesh, f), 1e-4);
    (void)vertices;
    EXPECT_TRUE(mesh.validate().empty());
  }
}

TEST(Fracture, RefusalsLeaveTheMeshUnchanged) {
  SurfaceMesh mesh = plate(10);
  const test::Snapshot before = test::snapshot(mesh);
  const float nan = std::nanf("");
  EXPECT_THROW(fracture(mesh, {5, 5, 1}, {}), InvalidInputError);   // no face within tolerance
  EXPECT_THROW(fracture(mesh, {20, 5, 0}, {}), InvalidInputError);  // outside the plate
  EXPECT_THROW(fracture(mesh, {nan, 5, 0}, {}), InvalidInputError);
  FractureOptions o;
  o.thickness = std::nan("");
  EXPECT_THROW(fracture(mesh, {5, 5, 0}, o), InvalidInputError);
  o = {};
  o.density = 0;
  EXPECT_THROW(fracture(mesh, {5, 5, 0}, o), InvalidInputError);
  o = {};
  o.material.rings[2].spacing = std::nan("");
  try {
    fracture(mesh, {5, 5, 0}, o);
    FAIL();
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("rings[2].spacing"), std::string::npos) << e.what();
  }
  o = {};
  o.material.rings[0].jitter = 2;
  EXPECT_THROW(fracture(mesh, {5, 5, 0}, o), InvalidInputError);
  o = {};
  o.material.grain_stretch = 2;
  o.material.grain = {};
  EXPECT_THROW(fracture(mesh, {5, 5, 0}, o), InvalidInputError);
  SurfaceMesh other = plate(2);
  FaceBvh foreign(other);
  EXPECT_THROW(fracture(mesh, {5, 5, 0}, {}, &foreign), InvalidInputError);
  EXPECT_TRUE(test::snapshot(mesh) == before);
  // A tolerance large enough accepts the point above the plate.
  o = {};
  o.tolerance = 1.5;
  EXPECT_FALSE(fracture(mesh, {5.2f, 5.1f, 1}, o).shards.empty());
  EXPECT_TRUE(mesh.validate().empty());
}

//! The message of the InvalidInputError `f` throws, or "" if it throws none.
template <typename F>
std::string refusal(F&& f) {
  try {
    f();
  } catch (const InvalidInputError& e) {
    return e.what();
  }
  return "";
}

TEST(Fracture, WorkIsBoundedRingsPointsAndThicknessAreLimitedBeforeTheMeshIsTouched) {
  SurfaceMesh mesh = plate(10);
  const test::Snapshot before = test::snapshot(mesh);
  FaceBvh bvh(mesh);
  // The hostile material: 1000 rings of 100000 points each ran for minutes. Now refused at once.
  FractureOptions o;
  o.material.name = "hostile";
  o.material.rings.assign(1000, FractureRing{100000, 1, 0});
  std::string what = refusal([&] { fracture(mesh, {5, 5, 0}, o, &bvh); });
  EXPECT_NE(what.find("rings[0].points brings the break points of rings[0..0] to 100000"), std::string::npos)
      << what;
  EXPECT_NE(what.find("limit of 10000"), std::string::npos) << what;
  // The limit over all rings, each ring within its own limit.
  o.material.rings.assign(3, FractureRing{4000, 1, 0});
  what = refusal([&] { fracture(mesh, {5, 5, 0}, o, &bvh); });
  EXPECT_NE(what.find("rings[2].points"), std::string::npos) << what;
  EXPECT_NE(what.find("12000"), std::string::npos) << what;
  o.material.rings.assign(kFractureMaxRings + 1, FractureRing{0, 1, 0});
  what = refusal([&] { fracture(mesh, {5, 5, 0}, o, &bvh); });
  EXPECT_NE(what.find("1001 rings, more than the limit of 1000"), std::string::npos) << what;
  // At the limits: accepted.
  o.material.rings.assign(kFractureMaxRings, FractureRing{0, 1e-3, 0});
  o.material.rings.back().points = static_cast<unsigned>(kFractureMaxPoints);
  EXPECT_EQ(fracture_break_points(o), kFractureMaxPoints);
  EXPECT_EQ(fracture_break_points({}), 40u);
  EXPECT_THROW((void)fracture_break_points(FractureOptions{.material = {.rings = {{100001, 1, 0}}}}),
               InvalidInputError);

  // A thickness beyond 10 diagonals of the mesh (the plate's is sqrt(200)): refused, naming the bound.
  o = {};
  o.thickness = 1e30;
  what = refusal([&] { fracture(mesh, {5, 5, 0}, o, &bvh); });
  EXPECT_NE(what.find("thickness is 1e+30"), std::string::npos) << what;
  EXPECT_NE(what.find("at most 141.42"), std::string::npos) << what;
  o.thickness = 10 * std::sqrt(200.0) * 1.001;
  EXPECT_THROW(fracture(mesh, {5, 5, 0}, o, &bvh), InvalidInputError);
  EXPECT_TRUE(test::snapshot(mesh) == before);

  // Within the limit: closed shards of finite volume.
  o.thickness = 10 * std::sqrt(200.0) * 0.999;
  const FractureResult r = fracture(mesh, {5.2f, 5.1f, 0}, o, &bvh);
  ASSERT_FALSE(r.shards.empty());
  for (const Shard& s : r.shards)
    EXPECT_TRUE(std::isfinite(s.mass.volume) && s.mass.volume < 1e6) << s.mass.volume;
}

TEST(Fracture, NoBreakPointsNoShardsMeshUnchanged) {
  SurfaceMesh mesh = plate(10);
  const test::Snapshot before = test::snapshot(mesh);
  FractureOptions o;
  o.material.rings = {{0, 1, 0}};
  const FractureResult r = fracture(mesh, {5.2f, 5.3f, 0}, o);
  EXPECT_TRUE(r.shards.empty());
  EXPECT_TRUE(test::snapshot(mesh) == before);
  EXPECT_TRUE(mesh.validate().empty());
}

TEST(Fracture, SingleTriangleIsTooSmallToBreakTwoBreak) {
  IndexedMesh one;
  one.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  one.indices = {0, 1, 2};
  SurfaceMesh mesh = build(one);
  const test::Snapshot before = test::snapshot(mesh);
  EXPECT_THROW(fracture(mesh, {0.2f, 0.2f, 0}, {}), InvalidInputError);
  EXPECT_TRUE(test::snapshot(mesh) == before);
  // Two triangles and a break radius beyond them: the whole small mesh breaks off, in more than one
  // piece (refined to the cells' size).
  SurfaceMesh two = plate(1);
  FractureOptions o;
  o.material.radius = 2;
  const FractureResult r = fracture(two, {0.3f, 0.6f, 0}, o);
  expect_sound(two, r, 1.0, 0);
  EXPECT_GE(r.shards.size(), 2u);
  EXPECT_EQ(two.n_faces(), 0u);
  EXPECT_TRUE(two.validate().empty());
}

TEST(Fracture, PropertiesFollowIntoShards) {
  SurfaceMesh mesh = test::textured_grid(30, true);
  auto material = mesh.add_face_property<int>("f:material", 0);
  for (Face f : mesh.faces()) material[f] = face_centroid(mesh, f).x < 15 ? 1 : 2;
  FractureOptions o;
  o.seed = 9;
  o.thickness = 0.3;
  const FractureResult r = fracture(mesh, {15.2f, 14.9f, 0}, o);
  EXPECT_TRUE(mesh.validate().empty());
  test::expect_corner_uv_matches_position(mesh);
  bool one = false, two = false;
  for (const Shard& s : r.shards) {
    ASSERT_TRUE(s.mesh.validate().empty());
    auto m = s.mesh.get_face_property<int>("f:material");
    auto uv = s.mesh.get_halfedge_property<Vec2>("h:texcoord");
    auto w = s.mesh.get_vertex_property<float>("v:weight");
    ASSERT_TRUE(m && uv && w);
    for (Face f : s.mesh.faces()) {
      const int id = m[f];
      EXPECT_TRUE(id == 1 || id == 2);
      one |= id == 1;
      two |= id == 2;
      for (Halfedge h : s.mesh.halfedges(f)) {
        const Vec3 p = s.mesh.position(s.mesh.to_vertex(h));
        EXPECT_NEAR(uv[h].x, p.x, 1e-4f);  // front, back and walls: the front vertex's UV
        EXPECT_NEAR(uv[h].y, p.y, 1e-4f);
      }
    }
    for (Vertex v : s.mesh.vertices()) EXPECT_NEAR(w[v], s.mesh.position(v).x, 1e-4f);
    // The front's faces keep the material of their side (the face at x < 15 is material 1).
    for (Face f : s.mesh.faces())
      if (std::abs(face_centroid(s.mesh, f).z) < 1e-6 && std::abs(face_centroid(s.mesh, f).x - 15) > 0.5f) {
        EXPECT_EQ(m[f], face_centroid(s.mesh, f).x < 15 ? 1 : 2);
      }
  }
  EXPECT_TRUE(one && two);
}

TEST(Fracture, RepeatedImpactsWithABvhAndAnImpactOnAShard) {
  SurfaceMesh mesh = plate(80);
  const double area = surface_area(mesh);
  FaceBvh bvh(mesh);
  double broken = 0;
  FractureOptions o;
  std::vector<Shard> shards;
  Vec3 last;
  for (int i = 0; i < 6; ++i) {
    o.seed = std::uint64_t(i);
    // Far enough apart that the broken areas (about 8.5 edges around each) do not meet.
    const Vec3 impact{15.3f + 25.f * float(i % 3), 20.7f + 38.f * float(i / 3), 0};
    FractureResult r = fracture(mesh, impact, o, &bvh);
    last = impact;
    ASSERT_FALSE(r.shards.empty());
    EXPECT_TRUE(bvh.up_to_date());
    for (Shard& s : r.shards) {
      broken += s.area;
      shards.push_back(std::move(s));
    }
    EXPECT_TRUE(mesh.validate().empty());
    // The tree answers as a scan over the edited mesh does.
    for (float x = 1.1f; x < 80; x += 9.7f) {
      const auto a = bvh.closest_point({x, 40.3f, 0.5f});
      const auto b = closest_point_linear(mesh, {x, 40.3f, 0.5f});
      ASSERT_EQ(a.has_value(), b.has_value());
      if (a) {
        EXPECT_EQ(a->face, b->face);
      }
    }
  }
  EXPECT_NEAR(surface_area(mesh) + broken, area, 1e-5 * area);
  // Near the same spot again: the rim of the hole breaks further.
  const auto rim = closest_point_linear(mesh, last);
  ASSERT_TRUE(rim.has_value());
  const double before = surface_area(mesh);
  const FractureResult again = fracture(mesh, rim->point, o, &bvh);
  double again_area = 0;
  for (const Shard& s : again.shards) again_area += s.area;
  EXPECT_GE(again.shards.size(), 10u);
  EXPECT_NEAR(surface_area(mesh) + again_area, before, 1e-5 * before);
  EXPECT_TRUE(mesh.validate().empty());
  // A shard breaks further: the largest one.
  auto largest = std::max_element(shards.begin(), shards.end(), [](const Shard& a, const Shard& b) {
    return a.mesh.n_faces() < b.mesh.n_faces();
  });
  SurfaceMesh piece = largest->mesh;
  const double piece_area = surface_area(piece);
  FractureOptions fine;
  fine.material = fracture_material("stone");
  fine.material.rings = {{3, 0.7, 0.2}};
  const Vec3 on = to_float(largest->centroid);
  const FractureResult r = fracture(piece, piece.position(Vertex(0)) * 0.5f + on * 0.5f, [&] {
    FractureOptions t = fine;
    t.tolerance = 1e-3;
    return t;
  }());
  expect_sound(piece, r, piece_area, 0);
  EXPECT_GE(r.shards.size(), 1u);
  EXPECT_TRUE(piece.validate().empty());
}

TEST(Fracture, PolygonFacesAreSplitWhereTheyBreak) {
  SurfaceMesh mesh = build(test::grid(30, false));
  const double area = surface_area(mesh);
  FractureOptions o;
  o.thickness = 0.05;
  const FractureResult r = fracture(mesh, {15.3f, 15.6f, 0}, o);
  expect_sound(mesh, r, area, o.thickness);
  EXPECT_GE(r.shards.size(), 20u);
  for (const Shard& s : r.shards) EXPECT_TRUE(s.mesh.is_triangle_mesh());
  EXPECT_TRUE(mesh.validate().empty());
}

TEST(Fracture, ModelUnitsRefineACoarseMesh) {
  SurfaceMesh mesh = plate(4);  // 32 triangles, edges of 1
  const double area = surface_area(mesh);
  FractureOptions o;
  o.material.rings = {{5, 0.3, 0.2}, {8, 0.4, 0.2}};
  o.material.units = FractureUnits::model;
  o.material.radius = 0.7;
  o.material.refine_edge = 0.15;
  const FractureResult r = fracture(mesh, {2.1f, 1.9f, 0}, o);
  expect_sound(mesh, r, area, 0);
  EXPECT_GE(r.shards.size(), 8u);
  for (const Shard& s : r.shards) {
    EXPECT_GE(s.mesh.n_faces(), 2u);
    for (Face f : s.mesh.faces())
      for (Halfedge h : s.mesh.halfedges(f))
        EXPECT_LE(
            norm(to_double(s.mesh.position(s.mesh.to_vertex(h)) - s.mesh.position(s.mesh.from_vertex(h)))),
            0.1501);
  }
  EXPECT_TRUE(mesh.validate().empty());
}

// Cells far smaller than the faces: the refinement stops after kFractureMaxRefineSplits splits in
// the strike (each adds at most two faces), and the shards are still sound.
TEST(Fracture, RefinementStopsAtItsLimitPerStrike) {
  SurfaceMesh mesh = plate(4);
  const double area = surface_area(mesh);
  const std::size_t before = mesh.n_faces();
  FractureOptions o;
  o.material.units = FractureUnits::model;
  o.material.radius = 1.5;
  o.material.refine_edge = 1e-4;
  const FractureResult r = fracture(mesh, {2.1f, 1.9f, 0}, o);
  expect_sound(mesh, r, area, 0);
  std::size_t faces = mesh.n_faces();
  for (const Shard& s : r.shards) faces += s.mesh.n_faces();
  EXPECT_GT(faces, before + kFractureMaxRefineSplits);
  EXPECT_LE(faces, before + 2 * kFractureMaxRefineSplits + 4);
}

// Random impacts over the meshes of data/: plates, closed and open surfaces. HEDGE_FRACTURE_IMPACTS
// sets how many (the full sweep: HEDGE_FRACTURE_IMPACTS=10000); HEDGE_FRACTURE_FIRST=i skips to
// impact i (the same impacts, the earlier ones not run) to look at one that failed.
TEST(Fracture, RandomImpactsOverRealMeshes) {
  std::size_t impacts = 240;
  if (const char* env = std::getenv("HEDGE_FRACTURE_IMPACTS")) impacts = std::strtoull(env, nullptr, 10);
  std::vector<SurfaceMesh> meshes;
  meshes.push_back(plate(30));
  for (const char* name : {"spot_triangulated.obj", "elephant-with-holes.off", "bob_small.ply",
                           "hourglass_ico.obj", "three_peaks.off", "fandisk_quads.off"})
    meshes.push_back(read_mesh(test::data_path(name)));
  // fandisk's quads are not planar, so their area depends on how they are split: triangulated here
  // (PolygonFacesAreSplitWhereTheyBreak covers planar polygons).
  ExportOptions fan;
  fan.triangulation = Triangulation::fan;
  meshes.back() = build(to_indexed(meshes.back(), fan));
  const std::vector<std::string> presets = fracture_material_names();
  TestRng rng{12345};
  std::size_t shards = 0;
  std::size_t first = 0;
  if (const char* env = std::getenv("HEDGE_FRACTURE_FIRST")) first = std::strtoull(env, nullptr, 10);
  for (std::size_t i = 0; i < impacts; ++i) {
    SurfaceMesh mesh = meshes[i % meshes.size()];
    std::vector<Face> faces(mesh.faces().begin(), mesh.faces().end());
    const Face f = faces[rng.next() % faces.size()];
    // A point inside the face's first fan triangle.
    double a = rng.uniform(), b = rng.uniform();
    if (a + b > 1) {
      a = 1 - a;
      b = 1 - b;
    }
    Halfedge h = mesh.halfedge(f);
    const Vec3d p0 = to_double(mesh.position(mesh.to_vertex(h)));
    h = mesh.next(h);
    const Vec3d p1 = to_double(mesh.position(mesh.to_vertex(h)));
    const Vec3d p2 = to_double(mesh.position(mesh.to_vertex(mesh.next(h))));
    const Vec3 impact = to_float(p0 + (p1 - p0) * a + (p2 - p0) * b);
    FractureOptions o;
    o.material = fracture_material(presets[(i / meshes.size()) % presets.size()]);
    o.seed = rng.next();
    o.thickness = i % 2 ? 0.002 * diagonal(mesh) : 0;
    o.tolerance = 1e-4 * diagonal(mesh);
    if (i < first) continue;
    const double area = surface_area(mesh);
    FractureResult r;
    try {
      r = fracture(mesh, impact, o);
    } catch (const InvalidInputError& e) {
      ADD_FAILURE() << "impact " << i << ": " << e.what();
      continue;
    }
    SCOPED_TRACE("impact " + std::to_string(i));
    expect_sound(mesh, r, area, o.thickness);
    shards += r.shards.size();
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(shards, impacts * 5);
  // No hull reports a vertex outside.
  EXPECT_EQ(g_hulls_outside, 0u) << g_hulls_outside << " of " << g_hulls;
}

TEST(Fracture, WithoutATreeTheTreeItMakesRefusesANonFinitePosition) {
  SurfaceMesh m = plate(8);
  test::expect_refuses_non_finite(m, Vertex(70), "FaceBvh", [&] { fracture(m, {4.2f, 3.9f, 0}); });
}

// With a tree, a strike reads only the positions of the broken area, as its cost is the area's: a
// face with a non-finite corner (written without the change log's notice) stays in the mesh, and
// no shard takes it.
TEST(Fracture, ANonFinitePositionInTheBrokenAreaStaysInTheMeshAndInNoShard) {
  SurfaceMesh m = plate(20);
  FaceBvh bvh(m);
  const Vec3 impact{10.3f, 10.4f, 0};
  const Vertex poisoned(12 * 21 + 10);  // (10, 12): inside the broken area, not a corner of the impact
  const Vec3 good = m.position(poisoned);
  test::poison(m, poisoned);
  FractureOptions o;
  o.seed = 5;
  o.material.refine_edge = 10;  // no refinement: the poisoned vertex's faces keep their shape
  const FractureResult r = fracture(m, impact, o, &bvh);
  ASSERT_GT(r.shards.size(), 3u);
  for (const Shard& s : r.shards) {
    for (Vertex v : s.mesh.vertices()) EXPECT_TRUE(is_finite(s.mesh.position(v)));
    EXPECT_EQ(s.mesh.validate(), std::vector<std::string>{});
  }
  ASSERT_TRUE(m.is_live(poisoned));
  EXPECT_EQ(m.valence(poisoned), 6u);  // its faces stayed
  m.position(poisoned) = good;
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
  // The broken area did reach it: without the NaN the same strike takes its faces.
  SurfaceMesh clean = plate(20);
  FaceBvh clean_bvh(clean);
  fracture(clean, impact, o, &clean_bvh);
  EXPECT_TRUE(!clean.is_live(poisoned) || clean.valence(poisoned) < 6u);
}

}  // namespace
}  // namespace hedge
