#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "caught.h"
#include "hedge/algorithms/fracture.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/locate.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/core/build.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "test_meshes.h"

namespace hedge {
namespace {

// A flat n x n plate of triangles in the z = 0 plane.
SurfaceMesh material_plate(int n) { return build(test::grid(n, true)); }

TEST(FractureMaterial, PresetsDifferInShardCount) {
  std::vector<std::size_t> counts;
  for (const char* name : {"glass", "stone", "ice"}) {
    SurfaceMesh mesh = material_plate(60);
    FractureOptions o;
    o.material = fracture_material(name);
    o.seed = 3;
    counts.push_back(fracture(mesh, {30.5f, 30.2f, 0}, o).shards.size());
    EXPECT_TRUE(mesh.validate().empty());
  }
  EXPECT_GT(counts[0], counts[2]);  // glass > ice
  EXPECT_GT(counts[2], counts[1]);  // ice > stone
  EXPECT_LE(counts[1], 7u);
}

TEST(FractureMaterial, UnknownPresetListsTheValidNames) {
  try {
    fracture_material("metal");
    FAIL();
  } catch (const InvalidInputError& e) {
    const std::string what = e.what();
    for (const char* n : {"metal", "glass", "stone", "wood", "ice"})
      EXPECT_NE(what.find(n), std::string::npos) << what;
  }
}

TEST(FractureMaterial, WoodShardsAreLongerAlongTheGrain) {
  auto mean_aspect = [](const char* preset, Vec3 grain) {
    SurfaceMesh mesh = material_plate(80);
    FractureOptions o;
    o.material = fracture_material(preset);
    o.material.grain = grain;
    o.seed = 11;
    const FractureResult r = fracture(mesh, {40.2f, 40.4f, 0}, o);
    EXPECT_TRUE(mesh.validate().empty());
    double sum = 0;
    for (const Shard& s : r.shards) {
      const BoundingBox b = bounding_box(s.mesh);
      sum += (b.max.x - b.min.x) / std::max(1e-6f, b.max.y - b.min.y);
    }
    return sum / double(r.shards.size());
  };
  EXPECT_GT(mean_aspect("wood", {1, 0, 0}), 1.8);
  EXPECT_LT(mean_aspect("wood", {0, 1, 0}), 1 / 1.8);
  // A grain along the plate's normal cuts across it: round cells.
  const double across = mean_aspect("wood", {0, 0, 1});
  EXPECT_GT(across, 0.6);
  EXPECT_LT(across, 1.6);
  const double glass = mean_aspect("glass", {});
  EXPECT_GT(glass, 0.6);
  EXPECT_LT(glass, 1.6);
}

TEST(FractureMaterial, RadiusIsTheSumOfTheSpacings) {
  EXPECT_DOUBLE_EQ(fracture_material_radius(fracture_material("glass")), 1.0 + 1.6 + 2.0 + 2.4);
  EXPECT_DOUBLE_EQ(fracture_material_radius(fracture_material("stone")), 7.5);
  EXPECT_EQ(fracture_material_radius(FractureMaterial{}), 0);
}

TEST(FractureMaterial, AtRadiusScalesSpacingsAndRefinementIntoModelUnits) {
  for (const std::string& name : fracture_material_names()) {
    const FractureMaterial preset = fracture_material(name);
    const FractureMaterial m = fracture_material_at_radius(preset, 0.25);
    const double scale = 0.25 / fracture_material_radius(preset);
    EXPECT_EQ(m.units, FractureUnits::model);
    EXPECT_EQ(m.radius, 0.25);
    EXPECT_NEAR(fracture_material_radius(m), 0.25, 1e-15);
    EXPECT_NEAR(m.refine_edge, preset.refine_edge * scale, 1e-15);
    ASSERT_EQ(m.rings.size(), preset.rings.size());
    for (std::size_t i = 0; i < m.rings.size(); ++i) {
      EXPECT_NEAR(m.rings[i].spacing, preset.rings[i].spacing * scale, 1e-15);
      EXPECT_EQ(m.rings[i].points, preset.rings[i].points);
      EXPECT_EQ(m.rings[i].jitter, preset.rings[i].jitter);
    }
    EXPECT_EQ(m.grain_stretch, preset.grain_stretch);
    EXPECT_EQ(m.name, preset.name);
  }
}

TEST(FractureMaterial, AtRadiusRefusesWhatHasNoRadius) {
  const FractureMaterial glass = fracture_material("glass");
  for (double r : {0.0, -1.0, std::nan(""), double(INFINITY)})
    EXPECT_THROW(fracture_material_at_radius(glass, r), InvalidInputError);
  std::string what =
      test::caught<InvalidInputError>([] { fracture_material_at_radius({}, 1); }, InvalidInputError(""))
          .what();
  EXPECT_NE(what.find("has no ring"), std::string::npos) << what;
  FractureMaterial bad = glass;
  bad.rings[1].spacing = 0;
  what = test::caught<InvalidInputError>([&] { fracture_material_at_radius(bad, 1); }, InvalidInputError(""))
             .what();
  EXPECT_NE(what.find("rings[1].spacing"), std::string::npos) << what;
}

// The share of a 10 x 10 plate that one glass strike breaks, the plate made of n x n quads.
double broken_share(int n, const FractureMaterial& material) {
  IndexedMesh im = test::grid(n, true);
  for (Vec3& p : im.positions) p = p * (10.0f / float(n));
  SurfaceMesh mesh = build(im);
  const double before = surface_area(mesh);
  FractureOptions o;
  o.material = material;
  o.seed = 2;
  const FractureResult r = fracture(mesh, {5.03f, 4.98f, 0}, o);
  EXPECT_TRUE(mesh.validate().empty());
  double broken = 0;
  for (const Shard& s : r.shards) {
    EXPECT_TRUE(s.mesh.validate().empty());
    broken += s.area;
  }
  return broken / before;
}

// A preset in edge lengths breaks a quarter of the share each time the resolution doubles; the same
// preset at a break radius in model units breaks about the same share at every resolution.
TEST(FractureMaterial, ABreakRadiusBreaksTheSameShareAtEveryResolution) {
  FractureMaterial glass = fracture_material("glass");
  glass.units = FractureUnits::edge_lengths;
  glass.radius = fracture_material_radius(glass);
  const double coarse = broken_share(20, glass), fine = broken_share(80, glass);
  EXPECT_LT(fine, coarse / 8);
  const FractureMaterial at_radius = fracture_material_at_radius(glass, 2);
  const double shares[] = {broken_share(10, at_radius), broken_share(20, at_radius),
                           broken_share(80, at_radius)};
  // The broken area reaches the outer ring plus half its spacing: about pi (2.34)^2 of 100.
  for (double share : shares) {
    EXPECT_GT(share, 0.12);
    EXPECT_LT(share, 0.24);
  }
}

// The share of spot's surface one strike on its flank breaks, after `steps` Loop subdivisions.
double spot_share(int steps, const FractureMaterial& material) {
  SurfaceMesh mesh = read_mesh(test::data_path("spot_triangulated.obj"));
  if (steps > 0) subdivide(mesh, Subdivision::loop, steps);
  const double before = surface_area(mesh);
  FaceBvh bvh(mesh);
  const std::optional<LocateResult> hit = bvh.closest_point({0.5f, 0.0f, 0.2f});
  EXPECT_TRUE(hit.has_value());
  FractureOptions o;
  o.material = material;
  o.seed = 7;
  const FractureResult r = fracture(mesh, hit->point, o, &bvh);
  EXPECT_TRUE(mesh.validate().empty());
  EXPECT_GE(r.shards.size(), 3u) << material.name;
  double broken = 0;
  for (const Shard& shard : r.shards) {
    EXPECT_TRUE(shard.mesh.validate().empty());
    broken += shard.area;
  }
  return broken / before;
}

// The presets' break radius is a fraction of the object's diagonal: one strike breaks the same share
// of spot at its native resolution and with 16 times the faces (two Loop steps), within 10%. In
// edge lengths of the impact face, the share fell by about 16 times.
TEST(FractureMaterial, EveryPresetBreaksTheSameShareOfSpotAtEveryResolution) {
  for (const std::string& name : fracture_material_names()) {
    const FractureMaterial preset = fracture_material(name);
    EXPECT_EQ(preset.units, FractureUnits::diagonal_fraction);
    const double x0 = spot_share(0, preset), x2 = spot_share(2, preset);
    EXPECT_GT(x0, 0.01) << name;
    EXPECT_LT(x0, 0.2) << name;
    EXPECT_LT(std::abs(x2 - x0), 0.1 * x0) << name << ": " << x0 << " at Loop x0, " << x2 << " at x2";
  }
  FractureMaterial glass = fracture_material("glass");
  glass.units = FractureUnits::edge_lengths;
  glass.radius = fracture_material_radius(glass);
  EXPECT_LT(spot_share(2, glass), spot_share(0, glass) / 8);
}

// The default strike (glass, seed 0) on spot at one of its vertices: every binding checks that it
// gets these numbers through its own door, so their defaults are the library's.
TEST(FractureMaterial, TheDefaultStrikeOnSpotThatEveryBindingChecks) {
  SurfaceMesh mesh = read_mesh(test::data_path("spot_triangulated.obj"));
  const FractureResult r = fracture(mesh, {0.380073f, -0.0641595f, 0.195141f});
  EXPECT_TRUE(mesh.validate().empty());
  ASSERT_EQ(r.shards.size(), 40u);
  double area = 0, mass = 0;
  for (const Shard& s : r.shards) {
    area += s.area;
    mass += s.mass.mass;
  }
  EXPECT_NEAR(area, 0.498213, 1e-6);
  EXPECT_NEAR(mass, 0.00838123, 1e-8);
  EXPECT_NEAR(r.break_radius, 0.336452, 1e-6);
}

// Units and radius are checked with the material, naming the field.
TEST(FractureMaterial, UnitsAndRadiusAreChecked) {
  EXPECT_STREQ(fracture_units_name(FractureUnits::diagonal_fraction), "diagonal_fraction");
  EXPECT_STREQ(fracture_units_name(FractureUnits::model), "model");
  EXPECT_STREQ(fracture_units_name(FractureUnits::edge_lengths), "edge_lengths");
  FractureOptions o;
  for (double r : {0.0, -1.0, std::nan(""), double(INFINITY)}) {
    o.material.radius = r;
    const std::string what =
        test::caught<InvalidInputError>([&] { fracture_break_points(o); }, InvalidInputError("")).what();
    EXPECT_NE(what.find("radius (the break radius, in diagonal_fraction) must be finite and positive"),
              std::string::npos)
        << what;
  }
  o.material.radius = 0.1;
  o.material.units = static_cast<FractureUnits>(5);
  const std::string what =
      test::caught<InvalidInputError>([&] { fracture_break_points(o); }, InvalidInputError("")).what();
  EXPECT_NE(what.find("units is 5"), std::string::npos) << what;
}

}  // namespace
}  // namespace hedge
