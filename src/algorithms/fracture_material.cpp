// Fracture materials: the presets and their scaling to a break radius in model units. See
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
