// hedge fracture IN --impact x,y,z --material NAME|FILE.json --seed S [--radius R --units U]
// [--break-radius R] -o DIR:
// [--format obj|glb] break a mesh at an impact and write the remaining mesh, one file per shard
// (OBJ, or glTF binary with one primitive per submesh) and summary.json into DIR.
// With --kind solid or auto, solid_fracture.cpp breaks it into closed pieces instead.
#include "hedge/algorithms/fracture.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>
#include <vector>

#include "binding/names.h"
#include "commands.h"
#include "hedge/algorithms/fracture_solid.h"
#include "hedge/error.h"
#include "load.h"
#include "material_json.h"
#include "numbers.h"
#include "progress_bar.h"
#include "solid_fracture.h"

namespace hedge::cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct FractureCommandOptions {
  std::string input, output, material = "glass", impact;
  std::uint64_t seed = 0;
  double thickness = 0, density = 1, tolerance = 0, break_radius = 0, radius = 0, shell_thickness = 0;
  std::string units;
  std::string format = "obj";  //!< of the mesh files written: "obj" or "glb"
  bool json = false;
  LoadOptions load;
  SolidFractureCliOptions solid;
};

}  // namespace

Vec3 parse_impact(const std::string& text) {
  Vec3 p;
  std::size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = text.find(',', start);
    if ((i < 2) != (comma != std::string::npos))
      throw CLI::ValidationError("--impact", "expected three numbers x,y,z, got '" + text + "'");
    const std::string part = text.substr(start, i < 2 ? comma - start : std::string::npos);
    double v = 0;
    const std::string why = finite_real(part, &v);
    if (!why.empty()) throw CLI::ValidationError("--impact", why + " (in '" + text + "')");
    p[static_cast<std::size_t>(i)] = static_cast<float>(v);
    start = comma + 1;
  }
  return p;
}

// ---- material files (schema: docs/fracture.md; parsed by material_json.cpp) ----

FractureMaterial read_material(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path, 0, -1, "cannot open the material file");
  // One byte past the limit is enough to refuse: a file (or a link to a device) is never read whole.
  std::string text(kMaterialMaxBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return parse_material_json(text, path);
}

FractureMaterial material_from(const std::string& text) {
  for (const std::string& n : fracture_material_names())
    if (n == text) return fracture_material(text);
  if (text.size() > 5 && text.substr(text.size() - 5) == ".json") return read_material(text);
  return fracture_material(text);  // throws, listing the presets
}

const FractureUnits kAllUnits[] = {FractureUnits::diagonal_fraction, FractureUnits::model,
                                   FractureUnits::edge_lengths};

FractureUnits units_from(const std::string& text) {
  for (FractureUnits u : kAllUnits)
    if (text == fracture_units_name(u)) return u;
  throw CLI::ValidationError("--units",
                             "must be diagonal_fraction, model or edge_lengths, got '" + text + "'");
}

json vec(const Vec3d& v) { return json::array({v.x, v.y, v.z}); }

//! Writes `text` to `path` through a temporary file in the same folder and a rename.
void write_atomically(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.string() + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.flush();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw IoError(path.string(), 0, -1, "cannot write");
    }
  }
  fs::rename(tmp, path);
}

namespace {

std::string shard_name(std::size_t i, const std::string& format) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "shard_%03zu.", i);
  return buf + format;
}

//! `solid_refusal`: why solid fracture was refused when --kind auto fell back to this (none when
//! surface fracture was asked for).
int run_surface_fracture(const FractureCommandOptions& o, const SolidFractureCheck& solid_refusal) {
  const Vec3 impact = parse_impact(o.impact);
  FractureOptions f;
  f.material = material_from(o.material);
  if (!o.units.empty()) f.material.units = units_from(o.units);
  if (o.radius > 0) f.material.radius = o.radius;
  if (o.break_radius > 0) f.material = fracture_material_at_radius(f.material, o.break_radius);
  f.shell_thickness = o.shell_thickness;
  f.seed = o.seed;
  f.thickness = o.thickness;
  f.density = o.density;
  f.tolerance = o.tolerance;
  LoadedMesh loaded = load_mesh(o.input, o.load);
  SurfaceMesh& mesh = loaded.mesh;
  const auto start = std::chrono::steady_clock::now();
  const FractureResult r = fracture(mesh, impact, f);
  const double ms = ms_since(start);

  // Everything is computed; only now is DIR touched. Each file is replaced atomically and
  // summary.json comes last, so a summary always describes complete files.
  const fs::path dir(o.output);
  fs::create_directories(dir);
  json summary;
  summary["input"] = fs::path(o.input).filename().string();
  summary["impact"] = vec(to_double(impact));
  summary["impact_on_surface"] = vec(to_double(r.impact_point));
  summary["material"] = f.material.name;
  summary["seed"] = o.seed;
  summary["units"] = fracture_units_name(f.material.units);
  summary["radius"] = f.material.radius;
  summary["break_radius"] = r.break_radius;
  summary["thickness"] = o.thickness;
  summary["density"] = o.density;
  if (solid_refusal.code != SolidRefusal::none) {
    summary["solid_refusal"] = solid_refusal.message;
    summary["solid_refusal_code"] = binding::name(solid_refusal.code);
  }
  const std::string remaining = "remaining." + o.format;
  summary["remaining"] = {{"file", remaining}, {"faces", mesh.n_faces()}, {"vertices", mesh.n_vertices()}};
  mesh.garbage_collection();
  save_mesh(mesh, (dir / remaining).string(), false);
  json shards = json::array();
  for (std::size_t i = 0; i < r.shards.size(); ++i) {
    const Shard& s = r.shards[i];
    const std::string name = shard_name(i, o.format);
    save_mesh(s.mesh, (dir / name).string(), false);
    json m = {{"mass", s.mass.mass},
              {"centre_of_mass", vec(s.mass.centre_of_mass)},
              {"inertia", s.mass.inertia},
              {"principal_moments", vec(s.mass.principal_moments)}};
    shards.push_back({{"file", name},
                      {"faces", s.mesh.n_faces()},
                      {"vertices", s.mesh.n_vertices()},
                      {"centroid", vec(s.centroid)},
                      {"area", s.area},
                      {"volume", s.mass.volume},
                      {"shell_thickness", s.shell_thickness},
                      {"closed", s.closed},
                      {"mass", m},
                      {"hull", {{"vertices", s.hull.mesh.n_vertices()}, {"faces", s.hull.mesh.n_faces()}}}});
  }
  summary["shards"] = shards;
  // Shard files of an earlier run with more shards, or in the other format, would not belong to
  // this summary.
  for (const std::string format : {"obj", "glb"}) {
    std::error_code ec;
    if (format != o.format) fs::remove(dir / ("remaining." + format), ec);
    for (std::size_t i = format == o.format ? r.shards.size() : 0;; ++i)
      if (!fs::remove(dir / shard_name(i, format), ec)) break;
  }
  write_atomically(dir / "summary.json", summary.dump(2) + "\n");

  if (o.json) {
    json out = summary;
    out["milliseconds"] = ms;
    out["seconds"] = {{"locate", r.seconds.locate},
                      {"scatter", r.seconds.scatter},
                      {"cut", r.seconds.cut},
                      {"detach", r.seconds.detach},
                      {"hulls", r.seconds.hulls}};
    std::printf("%s\n", out.dump(2).c_str());
  } else {
    std::printf("fractured %s at (%g, %g, %g) with %s: %zu shards into %s, %.2f ms\n", o.input.c_str(),
                impact.x, impact.y, impact.z, f.material.name.c_str(), r.shards.size(), o.output.c_str(), ms);
  }
  return kExitOk;
}

int run_fracture(const FractureCommandOptions& o) {
  if (o.solid.kind == "surface" && !o.solid.solid) return run_surface_fracture(o, {});
  const SolidFractureCliInputs in{o.input, o.output, o.impact,       o.material, o.seed,
                                  o.units, o.radius, o.break_radius, o.density,  o.tolerance,
                                  o.json,  o.load,   o.format};
  return run_solid_fracture(o.solid, in,
                            [&](const SolidFractureCheck& why) { return run_surface_fracture(o, why); });
}

void add_fracture_arguments(CLI::App* app, FractureCommandOptions* o) {
  app->add_option("IN", o->input, "Input mesh file")->required();
  app->add_option("--impact", o->impact,
                  "The impact point x,y,z, on (or within the tolerance of) the surface")
      ->required()
      ->check(CLI::Validator(
          [](std::string& s) -> std::string {
            try {
              parse_impact(s);
              return "";
            } catch (const CLI::ValidationError& e) {
              return e.what();
            }
          },
          "x,y,z"));
  app->add_option("--material", o->material,
                  "glass, stone, wood, ice, or a material file FILE.json (docs/fracture.md)")
      ->capture_default_str();
  add_seed_option(*app, o->seed, "Seed of the break points");
  app->add_option("--units", o->units,
                  "Units of the break radius: diagonal_fraction (of the mesh's bounding box, the presets), "
                  "model, or edge_lengths (of the impact face); default: the material's")
      ->check(CLI::IsMember({"diagonal_fraction", "model", "edge_lengths"}));
  add_real_option(*app, "--radius", o->radius,
                  "The break radius (the outer ring's) in the units; 0: the material's (glass 0.13, stone "
                  "0.14, wood and ice 0.11 of the diagonal)",
                  0);
  add_real_option(*app, "--break-radius", o->break_radius,
                  "The break radius in model units (the same as --units model --radius R, the material's "
                  "spacings scaled to it); 0: as --units and --radius say",
                  0);
  app->add_option("-o,--output", o->output, "Output folder (created if missing)")->required();
  app->add_option("--format", o->format,
                  "Format of the mesh files written: obj (usemtl runs per submesh) or glb (one primitive "
                  "and material per submesh, so solid pieces' caps carry the inner material)")
      ->check(CLI::IsMember({"obj", "glb"}))
      ->capture_default_str();
  add_real_option(*app, "--thickness", o->thickness,
                  "Extrude each shard into a solid this thick (model units); 0: none", 0);
  add_real_option(*app, "--density", o->density, "Mass per unit volume for the mass properties", 0, kInf,
                  true);
  add_real_option(*app, "--shell-thickness", o->shell_thickness,
                  "Open shards weigh as a thin shell this thick (model units); 0: 0.05 of the break radius",
                  0);
  add_real_option(
      *app, "--tolerance", o->tolerance,
      "Largest distance from the impact to the surface (model units); 0: 1e-3 of the nearest face's "
      "longest edge",
      0);
  add_json_flag(*app, o->json, "Print the summary as JSON, with timings");
  add_solid_fracture_arguments(*app, o->solid);
  app->callback([o] {
    const bool solid = o->solid.solid || o->solid.kind != "surface";
    if (solid && o->units == "edge_lengths")
      throw CLI::ValidationError("--units",
                                 "solid fracture takes its break radius in model units or as a "
                                 "fraction of the diagonal, not in edge_lengths");
  });
}

}  // namespace

const CommandBinder fracture_command =
    bind_command<FractureCommandOptions, add_fracture_arguments, run_fracture>;

}  // namespace hedge::cli
