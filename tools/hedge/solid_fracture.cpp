// hedge fracture IN --kind solid|auto (or --solid) --impact x,y,z [--break-radius R |
// --units U --radius R]
// -o DIR [--format obj|glb]: break a closed mesh into closed pieces and write the remaining object,
// one file per piece (OBJ with usemtl runs, or glTF binary with a primitive and material per submesh:
// the caps' inner material) and summary.json (with the bond graph) into DIR. "auto" falls back to surface
// fracture where solid fracture is refused for the input's shape (solid_refusal_falls_back(): open or
// non-manifold); any other refusal is an error.
#include "solid_fracture.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

#include "commands.h"
#include "hedge/algorithms/fracture_solid.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/error.h"
#include "numbers.h"
#include "progress_bar.h"

namespace hedge::cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string piece_name(std::size_t i, const std::string& format) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "piece_%03zu.", i);
  return buf + format;
}

json mass_json(const MassProperties& m) {
  return {{"mass", m.mass},
          {"centre_of_mass", vec(m.centre_of_mass)},
          {"inertia", m.inertia},
          {"principal_moments", vec(m.principal_moments)},
          {"principal_axes",
           json::array({vec(m.principal_axes[0]), vec(m.principal_axes[1]), vec(m.principal_axes[2])})}};
}

std::size_t inner_faces(const SurfaceMesh& mesh) {
  const auto inner = mesh.get_face_property<std::uint8_t>(kInnerProperty);
  std::size_t n = 0;
  if (inner)
    for (Face f : mesh.faces()) n += inner[f] != 0;
  return n;
}

json piece_json(const SolidPiece& p, const std::string& file) {
  return {{"file", file},
          {"faces", p.mesh.n_faces()},
          {"vertices", p.mesh.n_vertices()},
          {"inner_faces", inner_faces(p.mesh)},
          {"centroid", vec(p.centroid)},
          {"volume", p.volume},
          {"cap_area", p.cap_area},
          {"mass", mass_json(p.mass)},
          {"hull", {{"vertices", p.hull.mesh.n_vertices()}, {"faces", p.hull.mesh.n_faces()}}}};
}

json bonds_json(const std::vector<SolidBond>& bonds) {
  json out = json::array();
  for (const SolidBond& b : bonds)
    out.push_back(
        {{"a", b.a}, {"b", b.b == kSolidRemaining ? json("remaining") : json(b.b)}, {"area", b.area}});
  return out;
}

//! The enclosed volume, or null when the mesh is open (somewhere far from the impact, since the
//! strike checks the broken region only).
json volume_or_null(const SurfaceMesh& mesh) {
  try {
    return volume(mesh);
  } catch (const InvalidInputError&) {
    return nullptr;
  }
}

SolidFractureOptions solid_options(const SolidFractureCliOptions& s, const SolidFractureCliInputs& in) {
  SolidFractureOptions o;
  o.material = material_from(in.material);
  if (in.break_radius > 0) {
    o.radius = in.break_radius;
  } else if (in.radius > 0) {
    const std::string units = in.units.empty() ? fracture_units_name(o.material.units) : in.units;
    if (units == "model")
      o.radius = in.radius;
    else if (units == "diagonal_fraction")
      o.radius_fraction = in.radius;
    else  // a material file in edge lengths (--units edge_lengths is a usage error)
      throw InvalidInputError("fracture: material '" + o.material.name + "' sizes its rings in " + units +
                              ": solid fracture takes its break radius in model units or as a fraction of "
                              "the diagonal (give --break-radius or --units)");
  }
  o.seed = in.seed;
  o.density = in.density;
  o.tolerance = in.tolerance;
  o.inner_submesh = s.inner_submesh;
  return o;
}

}  // namespace

int run_solid_fracture(const SolidFractureCliOptions& s, const SolidFractureCliInputs& in,
                       const std::function<int(const SolidFractureCheck&)>& surface) {
  const Vec3 impact = parse_impact(in.impact);
  const SolidFractureOptions f = solid_options(s, in);
  LoadedMesh loaded = load_mesh(in.input, in.load);
  SurfaceMesh& mesh = loaded.mesh;
  // The refusal checks the broken region only, as the strike would, before anything changes; both
  // find it through one tree.
  const json input_volume = volume_or_null(mesh);
  const auto start = std::chrono::steady_clock::now();  // the tree's build included, as surface fracture's
  FaceBvh bvh(mesh);
  const SolidFractureCheck why = solid_fracture_check(mesh, impact, f, &bvh);
  if (why.code != SolidRefusal::none) {
    // "auto" falls back for the input's shape only (solid_refusal_falls_back()); a bad impact or
    // option is an error, as with --kind solid.
    if (s.kind != "auto" || s.solid || !solid_refusal_falls_back(why.code))
      throw InvalidInputError(in.input + ": cannot be broken as a solid: " + why.message);
    std::fprintf(stderr, "hedge: solid fracture refused (%s); surface fracture instead\n",
                 why.message.c_str());
    return surface(why);
  }
  SolidFractureResult r = fracture_solid(mesh, impact, f, &bvh);
  const double ms = ms_since(start);

  // Everything is computed; only now is DIR touched. Each file is replaced atomically and
  // summary.json comes last, so a summary always describes complete files.
  const fs::path dir(in.output);
  fs::create_directories(dir);
  json summary;
  summary["input"] = fs::path(in.input).filename().string();
  summary["kind"] = "solid";
  summary["impact"] = vec(to_double(impact));
  summary["impact_on_surface"] = vec(to_double(r.impact_point));
  summary["material"] = f.material.name;
  summary["seed"] = in.seed;
  summary["radius"] = r.radius;
  summary["density"] = in.density;
  summary["input_volume"] = input_volume;
  mesh.garbage_collection();
  const std::string remaining = "remaining." + in.format;
  summary["remaining"] = {{"file", remaining},
                          {"faces", mesh.n_faces()},
                          {"vertices", mesh.n_vertices()},
                          {"inner_faces", inner_faces(mesh)},
                          {"volume", volume_or_null(mesh)}};
  save_mesh(mesh, (dir / remaining).string(), false);
  json pieces = json::array();
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    const std::string name = piece_name(i, in.format);
    save_mesh(r.pieces[i].mesh, (dir / name).string(), false);
    pieces.push_back(piece_json(r.pieces[i], name));
  }
  summary["pieces"] = pieces;
  summary["bonds"] = bonds_json(r.bonds);
  // Piece files of an earlier run with more pieces, or in the other format, would not belong to
  // this summary.
  for (const std::string format : {"obj", "glb"}) {
    std::error_code ec;
    if (format != in.format) fs::remove(dir / ("remaining." + format), ec);
    for (std::size_t i = format == in.format ? r.pieces.size() : 0;; ++i)
      if (!fs::remove(dir / piece_name(i, format), ec)) break;
  }
  write_atomically(dir / "summary.json", summary.dump(2) + "\n");

  if (in.json) {
    json out = summary;
    out["milliseconds"] = ms;
    out["seconds"] = {{"locate", r.seconds.locate},     {"cells", r.seconds.cells},
                      {"clip", r.seconds.clip},         {"cap", r.seconds.cap},
                      {"assemble", r.seconds.assemble}, {"per_piece", r.seconds.per_piece}};
    std::printf("%s\n", out.dump(2).c_str());
  } else {
    std::printf(
        "fractured %s (solid) at (%g, %g, %g) with %s, radius %g: %zu pieces, %zu bonds into %s, %.2f ms\n",
        in.input.c_str(), impact.x, impact.y, impact.z, f.material.name.c_str(), r.radius, r.pieces.size(),
        r.bonds.size(), in.output.c_str(), ms);
  }
  return kExitOk;
}

void add_solid_fracture_arguments(CLI::App& app, SolidFractureCliOptions& o) {
  CLI::Option* kind =
      app.add_option(
             "--kind", o.kind,
             "surface: shards of the surface; solid: closed pieces of a closed mesh, their cut faces "
             "capped (f:inner, f:submesh), and the bond graph in summary.json; auto: solid where "
             "the mesh allows it, else surface where it is open or non-manifold, saying why on stderr and "
             "in summary.json (solid_refusal, and solid_refusal_code \"open\" or \"non_manifold\"; a "
             "bad impact or option is an error)")
          ->check(CLI::IsMember({"surface", "solid", "auto"}))
          ->capture_default_str();
  app.add_flag("--solid", o.solid, "The same as --kind solid")->excludes(kind);
  app.add_option("--inner-submesh", o.inner_submesh,
                 "Solid fracture: the f:submesh of the cap faces; -1: one more than the mesh's largest")
      ->capture_default_str()
      ->check(CLI::Range(-1, 2147483647));
}

}  // namespace hedge::cli
