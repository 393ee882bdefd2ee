// hedge fracture --kind solid|auto: what the fracture command (fracture.cpp) and the solid fracture
// (solid_fracture.cpp) share: the parsing of the impact and the material, the atomic writes, and
// the solid fracture's own option block.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "hedge/algorithms/fracture.h"
#include "hedge/algorithms/fracture_solid.h"
#include "hedge/core/vec.h"
#include "load.h"

namespace hedge::cli {

//! "x,y,z" to a point. \throw CLI::ValidationError naming --impact.
Vec3 parse_impact(const std::string& text);
//! A material file (docs/fracture.md). \throw IoError, InvalidInputError naming the file and field.
FractureMaterial read_material(const std::string& path);
//! A preset's name or a material file FILE.json.
FractureMaterial material_from(const std::string& text);
nlohmann::json vec(const Vec3d& v);
//! Writes `text` to `path` through a temporary file in the same folder and a rename.
void write_atomically(const std::filesystem::path& path, const std::string& text);

//! The options only solid fracture has.
struct SolidFractureCliOptions {
  //! "surface", "solid" or "auto" (solid where solid_fracture_refusal() allows it, else surface).
  std::string kind = "surface";
  //! --solid: the same as --kind solid.
  bool solid = false;
  std::int32_t inner_submesh = -1;
};

//! What solid fracture takes from the fracture command's common options.
struct SolidFractureCliInputs {
  const std::string &input, &output, &impact, &material;
  std::uint64_t seed;
  //! The break radius as the surface fracture takes it: --break-radius in model units, or --radius
  //! in --units (the material's when not given: a fraction of the diagonal for the presets).
  const std::string& units;
  double radius, break_radius;
  double density, tolerance;
  bool json;
  const LoadOptions& load;
  //! Of the mesh files written: "obj" or "glb".
  const std::string& format;
};

void add_solid_fracture_arguments(CLI::App& app, SolidFractureCliOptions& options);

//! Breaks IN into closed pieces and writes them, the remaining object and summary.json to the
//! output folder. With kind "auto", where solid fracture is refused, says why on stderr and calls
//! `surface` with the refusal (its code and message, for summary.json) instead.
int run_solid_fracture(const SolidFractureCliOptions& options, const SolidFractureCliInputs& in,
                       const std::function<int(const SolidFractureCheck&)>& surface);

}  // namespace hedge::cli
