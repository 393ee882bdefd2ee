// Fracture materials: the presets, their scaling to a break radius in model units, and the checks
// of a material and the options (fracture_break_points()). See
// include/hedge/algorithms/fracture.h for the contract.
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "format.h"
#include "hedge/algorithms/fracture.h"
#include "hedge/error.h"

namespace hedge {

using detail::number;

namespace {
constexpr unsigned kMaxRingPoints = 100000;  // on one ring
}  // namespace

const char* fracture_units_name(FractureUnits units) {
  switch (units) {
    case FractureUnits::edge_lengths:
      return "edge_lengths";
    case FractureUnits::model:
      return "model";
    case FractureUnits::diagonal_fraction:
      return "diagonal_fraction";
  }
  return "unknown";
}

std::vector<std::string> fracture_material_names() { return {"glass", "stone", "wood", "ice"}; }

FractureMaterial fracture_material(std::string_view preset) {
  FractureMaterial m;
  m.name = std::string(preset);
  m.units = FractureUnits::diagonal_fraction;
  if (preset == "glass") {
    m.rings = {{4, 1.0, 0.4}, {8, 1.6, 0.4}, {12, 2.0, 0.35}, {16, 2.4, 0.3}};
    m.radius = 0.13;
  } else if (preset == "stone") {
    m.rings = {{3, 3.0, 0.3}, {4, 4.5, 0.3}};
    m.refine_edge = 2.0;
    m.radius = 0.14;
  } else if (preset == "wood") {
    m.rings = {{4, 1.5, 0.3}, {6, 2.0, 0.3}, {8, 2.5, 0.3}};
    m.grain = {1, 0, 0};
    m.grain_stretch = 3;
    m.radius = 0.11;
  } else if (preset == "ice") {
    m.rings = {{6, 1.5, 0.5}, {9, 2.0, 0.5}, {11, 2.5, 0.5}};
    m.radius = 0.11;
  } else {
    std::string names;
    for (const std::string& n : fracture_material_names()) names += (names.empty() ? "" : ", ") + n;
    throw InvalidInputError("fracture: unknown material '" + std::string(preset) +
                            "'; valid presets: " + names);
  }
  return m;
}

// The options' checks, before anything is touched: every field of the material and the options,
// naming it. Returns the break points of all rings.
std::size_t fracture_break_points(const FractureOptions& o) {
  auto fail = [](const std::string& what) { throw InvalidInputError("fracture: " + what); };
  const FractureMaterial& m = o.material;
  if (m.rings.size() > kFractureMaxRings)
    fail("material '" + m.name + "' has " + std::to_string(m.rings.size()) +
         " rings, more than the limit of " + std::to_string(kFractureMaxRings) +
         " (kFractureMaxRings); use fewer, wider rings");
  std::size_t total = 0;
  for (std::size_t i = 0; i < m.rings.size(); ++i) {
    const FractureRing& r = m.rings[i];
    const std::string where = "material '" + m.name + "' rings[" + std::to_string(i) + "].";
    if (r.points > kMaxRingPoints)
      fail(where + "points is " + std::to_string(r.points) + ", more than " + std::to_string(kMaxRingPoints));
    if (!std::isfinite(r.spacing) || r.spacing <= 0)
      fail(where + "spacing must be finite and positive, is " + number(r.spacing));
    if (!std::isfinite(r.jitter) || r.jitter < 0 || r.jitter > 1)
      fail(where + "jitter must be in [0, 1], is " + number(r.jitter));
    total += r.points;
    if (total > kFractureMaxPoints)
      fail(where + "points brings the break points of rings[0.." + std::to_string(i) + "] to " +
           std::to_string(total) + ", more than the limit of " + std::to_string(kFractureMaxPoints) +
           " in all rings (kFractureMaxPoints); use fewer points");
  }
  const std::string mat = "material '" + m.name + "' ";
  if (!std::isfinite(m.grain_stretch) || m.grain_stretch < 1)
    fail(mat + "grain_stretch must be finite and at least 1, is " + number(m.grain_stretch));
  if (!is_finite(m.grain)) fail(mat + "grain is not finite");
  if (m.grain_stretch > 1 && dot(to_double(m.grain), to_double(m.grain)) == 0)
    fail(mat + "grain is zero while grain_stretch is " + number(m.grain_stretch));
  if (!std::isfinite(m.refine_edge) || m.refine_edge <= 0)
    fail(mat + "refine_edge must be finite and positive, is " + number(m.refine_edge));
  if (m.units != FractureUnits::edge_lengths && m.units != FractureUnits::model &&
      m.units != FractureUnits::diagonal_fraction)
    fail(mat + "units is " + std::to_string(static_cast<std::int32_t>(m.units)) +
         ", not one of edge_lengths (0), model (1), diagonal_fraction (2)");
  if (!std::isfinite(m.radius) || m.radius <= 0)
    fail(mat + "radius (the break radius, in " + fracture_units_name(m.units) +
         ") must be finite and positive, is " + number(m.radius));
  if (!std::isfinite(o.thickness) || o.thickness < 0)
    fail("thickness must be finite and >= 0, is " + number(o.thickness));
  if (!std::isfinite(o.relative_thickness) || o.relative_thickness < 0 ||
      o.relative_thickness > kFractureMaxRelativeThickness)
    fail("relative_thickness must be in [0, " + number(kFractureMaxRelativeThickness) +
         "] (kFractureMaxRelativeThickness: a solid at most as thick as the break radius), is " +
         number(o.relative_thickness));
  if (o.thickness > 0 && o.relative_thickness > 0)
    fail("thickness (" + number(o.thickness) + ") and relative_thickness (" + number(o.relative_thickness) +
         ") are both set; give one of them");
  if (o.inner_submesh < -1)
    fail("inner_submesh must be -1 (automatic) or >= 0, is " + std::to_string(o.inner_submesh));
  if (!std::isfinite(o.density) || o.density <= 0)
    fail("density must be finite and positive, is " + number(o.density));
  if (!std::isfinite(o.shell_thickness) || o.shell_thickness < 0)
    fail("shell_thickness must be finite and >= 0 (0: automatic), is " + number(o.shell_thickness));
  if (!std::isfinite(o.tolerance) || o.tolerance < 0)
    fail("tolerance must be finite and >= 0, is " + number(o.tolerance));
  return total;
}

double fracture_material_radius(const FractureMaterial& material) {
  double outer = 0;
  for (const FractureRing& r : material.rings) outer += r.spacing;
  return outer;
}

FractureMaterial fracture_material_at_radius(FractureMaterial material, double radius) {
  if (!std::isfinite(radius) || radius <= 0)
    throw InvalidInputError("the break radius must be finite and positive, is " + number(radius) +
                            " (fracture_material_at_radius)");
  if (material.rings.empty())
    throw InvalidInputError("fracture_material_at_radius: material '" + material.name +
                            "' has no ring, so no radius to scale");
  for (std::size_t i = 0; i < material.rings.size(); ++i)
    if (!std::isfinite(material.rings[i].spacing) || material.rings[i].spacing <= 0)
      throw InvalidInputError("fracture_material_at_radius: material '" + material.name + "' rings[" +
                              std::to_string(i) + "].spacing must be finite and positive, is " +
                              number(material.rings[i].spacing));
  const double scale = radius / fracture_material_radius(material);
  for (FractureRing& r : material.rings) r.spacing *= scale;
  material.refine_edge *= scale;
  material.units = FractureUnits::model;
  material.radius = radius;
  return material;
}

}  // namespace hedge
