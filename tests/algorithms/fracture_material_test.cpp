#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "caught.h"
#include "hedge/algorithms/fracture.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/core/build.h"
#include "hedge/error.h"
#include "test_meshes.h"

namespace hedge {
namespace {

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
    EXPECT_TRUE(m.absolute);
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
  const FractureMaterial glass = fracture_material("glass");
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

}  // namespace
}  // namespace hedge
