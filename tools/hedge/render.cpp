// hedge render: pictures of meshes, headless. A shaded picture (PNG), several meshes side by side
// with captions (--grid), or the half-edge diagram of a small mesh (--halfedges, PNG or SVG).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "commands.h"
#include "hedge/error.h"
#include "load.h"
#include "memory_budget.h"
#include "numbers.h"
#include "picture/diagram.h"
#include "picture/shaded.h"
#include "picture/sheet.h"
#include "progress_bar.h"

namespace hedge::cli {

namespace {

using namespace hedge::picture;

struct RenderCommandOptions {
  std::string input;
  std::vector<std::string> grid;
  std::string output;
  std::string size = "800x600";
  std::string view = "iso";
  std::vector<double> eye, target, up;
  double fov = 30;
  std::string shading = "smooth";
  std::string color_by = "none";
  bool wireframe = false;
  double feature_angle = 60;
  int supersample = 2;
  int columns = 0;
  unsigned threads = 0;
  bool halfedges = false;
  std::size_t max_faces = 400;
  LoadOptions load;
};

// "WxH" -> (W, H), each side a whole number that fits an int; nothing if malformed.
std::optional<std::pair<int, int>> parse_size(const std::string& text) {
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos) return std::nullopt;
  const std::optional<long> w = parse_integer<long>(std::string_view(text).substr(0, x));
  const std::optional<long> h = parse_integer<long>(std::string_view(text).substr(x + 1));
  if (!w || !h) return std::nullopt;
  // A side beyond an int is refused by check_size all the same: clamp it rather than wrap it.
  auto clamp = [](long v) {
    return int(std::clamp<long>(v, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
  };
  return std::pair{clamp(*w), clamp(*h)};
}

std::string size_check(const std::string& text) {
  const std::string expected = "expected WIDTHxHEIGHT, two whole numbers such as 800x600, got '" + text + "'";
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos) return expected;
  for (const std::string& side : {text.substr(0, x), text.substr(x + 1)}) {
    const std::optional<long> v = parse_integer<long>(side);
    const bool digits = !side.empty() && side.find_first_not_of("0123456789") == std::string::npos;
    if (!v && !digits) return expected;
    if (!v || *v < 1 || *v > kMaxSide)
      return "each side must be from 1 to " + std::to_string(kMaxSide) + " pixels, got " + side + " in '" +
             text + "'";
  }
  const auto size = parse_size(text);
  try {
    check_size(size->first, size->second, "a picture");
  } catch (const InvalidInputError& e) {
    return e.what();
  }
  return "";
}

bool ends_with(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  std::string tail = s.substr(s.size() - suffix.size());
  std::transform(tail.begin(), tail.end(), tail.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return tail == suffix;
}

// Mesh vertices that repair split off another: they came from the same input vertex as another.
std::vector<Vertex> repaired_vertices(const LoadedMesh& loaded) {
  std::unordered_map<Index, int> uses;
  for (Index origin : loaded.report.vertex_origin) ++uses[origin];
  std::vector<Vertex> out;
  for (std::size_t v = 0; v < loaded.report.vertex_origin.size(); ++v)
    if (uses[loaded.report.vertex_origin[v]] > 1) out.push_back(Vertex(Index(v)));
  return out;
}

//! The explicit camera of --eye, --target, --up and --fov, if --eye is given.
std::optional<Camera> explicit_camera(const RenderCommandOptions& o) {
  if (o.eye.empty()) return std::nullopt;
  Camera c;
  c.eye = {o.eye[0], o.eye[1], o.eye[2]};
  c.target = {o.target[0], o.target[1], o.target[2]};
  if (!o.up.empty()) c.up = {o.up[0], o.up[1], o.up[2]};
  c.fov_degrees = o.fov;
  return c;
}

Image picture_of(const std::string& path, const RenderCommandOptions& o, int w, int h, LoadedMesh& loaded) {
  loaded = load_mesh(path, o.load);
  if (loaded.mesh.n_faces() == 0) throw InvalidInputError(path + ": nothing to draw: the mesh has no faces");
  ShadedOptions s;
  s.width = w;
  s.height = h;
  s.view = view_named(o.view);
  s.camera = explicit_camera(o);
  s.shading = shading_named(o.shading);
  s.color_by = color_by_named(o.color_by);
  s.wireframe = o.wireframe;
  s.feature_angle = o.feature_angle;
  s.supersample = o.supersample;
  s.threads = o.threads;
  s.marked = repaired_vertices(loaded);
  return shaded_picture(loaded.mesh, s);
}

std::string caption_of(const std::string& path, const SurfaceMesh& m) {
  return std::filesystem::path(path).filename().string() + ": " + std::to_string(m.n_vertices()) + " V, " +
         std::to_string(m.n_faces()) + " F";
}

int run_render(const RenderCommandOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const auto [w, h] = *parse_size(o.size);
  const bool svg = ends_with(o.output, ".svg");
  if (!svg && !ends_with(o.output, ".png"))
    throw InvalidInputError("the output must end in .png (or .svg for --halfedges): " + o.output);
  if (svg && !o.halfedges)
    throw InvalidInputError("SVG output is for half-edge diagrams (--halfedges); use .png for " + o.output);

  const std::filesystem::path parent = std::filesystem::path(o.output).parent_path();
  std::string what;
  if (o.halfedges) {
    const LoadedMesh loaded = load_mesh(o.input, o.load);
    DiagramOptions d;
    d.max_faces = o.max_faces;
    const std::optional<Camera> given = explicit_camera(o);
    const Camera camera = given ? *given : diagram_camera(loaded.mesh, double(w) / h);
    if (!parent.empty()) std::filesystem::create_directories(parent);
    if (svg) {
      SvgCanvas canvas(w, h);
      draw_halfedge_diagram(loaded.mesh, camera, canvas, d);
      write_file_atomic(o.output, canvas.svg());
    } else {
      Image image(w, h);
      ImageCanvas canvas(image);
      draw_halfedge_diagram(loaded.mesh, camera, canvas, d);
      write_png(image, o.output);
    }
    what = "the half-edge diagram of " + o.input + " (" + std::to_string(loaded.mesh.n_halfedges()) +
           " half-edges)";
  } else if (!o.grid.empty()) {
    // The sheet's size and memory before any panel is drawn: every panel is kept for the sheet.
    int sheet_w = 0, sheet_h = 0;
    check_contact_sheet(o.grid.size(), w, h, o.columns, &sheet_w, &sheet_h);
    check_memory(shaded_picture_bytes(w, h, o.supersample) + 3.0 * w * h * double(o.grid.size()) +
                     3.0 * sheet_w * sheet_h,
                 o.load.memory, "a sheet of " + std::to_string(o.grid.size()) + " pictures of " + o.size,
                 "use a smaller --size, a lower --supersample or fewer meshes");
    std::vector<Panel> panels;
    for (const std::string& path : o.grid) {
      LoadedMesh loaded;
      Image image = picture_of(path, o, w, h, loaded);
      panels.push_back({std::move(image), caption_of(path, loaded.mesh)});
    }
    const Image sheet = contact_sheet(panels, o.columns);
    if (!parent.empty()) std::filesystem::create_directories(parent);
    write_png(sheet, o.output);
    what = std::to_string(panels.size()) + " meshes side by side (" + std::to_string(sheet.width()) + "x" +
           std::to_string(sheet.height()) + ")";
  } else {
    check_memory(shaded_picture_bytes(w, h, o.supersample), o.load.memory, "a picture of " + o.size,
                 "use a smaller --size or a lower --supersample");
    LoadedMesh loaded;
    const Image image = picture_of(o.input, o, w, h, loaded);
    if (!parent.empty()) std::filesystem::create_directories(parent);
    write_png(image, o.output);
    what = o.input + " (" + std::to_string(loaded.mesh.n_faces()) + " faces, " + std::to_string(w) + "x" +
           std::to_string(h) + ")";
  }
  const double ms = ms_since(start);
  std::printf("wrote %s: %s in %.0f ms\n", o.output.c_str(), what.c_str(), ms);
  return kExitOk;
}

//! An option of three comma-separated coordinates, x,y,z.
void add_point_option(CLI::App* app, const char* name, std::vector<double>& point, const char* help) {
  app->add_option(name, point, help)->delimiter(',')->expected(3)->transform(real_number(-kInf, kInf));
}

void add_render_arguments(CLI::App* app, RenderCommandOptions* o) {
  add_mesh_file_argument(*app, o->input, false);
  app->add_option("-o,--output", o->output, "Picture to write: .png, or .svg with --halfedges")->required();
  app->add_option("--grid", o->grid, "Several mesh files, drawn side by side with captions")->expected(1, -1);
  app->add_option("--columns", o->columns, "Pictures per row with --grid (0: all in one row)")
      ->transform(whole_number<int>(0));
  app->add_option("--size", o->size, "Picture size WIDTHxHEIGHT (per mesh with --grid)")
      ->capture_default_str()
      ->check(CLI::Validator(size_check, "WxH", "size"));
  app->add_option("--view", o->view, std::string("Camera: ") + view_names())
      ->capture_default_str()
      ->check(CLI::IsMember({"front", "back", "left", "right", "top", "bottom", "iso"}));
  add_point_option(app, "--eye", o->eye, "Explicit camera position x,y,z (with --target)");
  add_point_option(app, "--target", o->target, "Point the explicit camera looks at, x,y,z");
  add_point_option(app, "--up", o->up, "Up direction of the explicit camera, x,y,z (default 0,1,0)");
  add_real_option(*app, "--fov", o->fov,
                  "Vertical field of view in degrees of the explicit camera (0: orthographic)", 0, 179);
  app->add_option("--shading", o->shading, "flat or smooth")
      ->capture_default_str()
      ->check(CLI::IsMember({"flat", "smooth"}));
  app->add_option("--color-by", o->color_by, "none, face, shard (connected piece), curvature or valence")
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "face", "shard", "curvature", "valence"}));
  app->add_flag("--wireframe", o->wireframe, "Draw every edge");
  add_real_option(*app, "--feature-angle", o->feature_angle,
                  "Highlight edges whose faces meet at more than this angle, in degrees (0: none)", 0, 180);
  app->add_option("--supersample", o->supersample, "Samples per pixel along each axis, 1..4 (anti-aliasing)")
      ->capture_default_str()
      ->transform(whole_number<int>(1, 4));
  app->add_option("--threads", o->threads, "Threads (0: every core, at most 16 are used)")
      ->capture_default_str()
      ->transform(whole_number<unsigned>(0));
  app->add_flag("--halfedges", o->halfedges, "Draw the half-edge diagram of a small mesh instead");
  app->add_option("--max-faces", o->max_faces, "Largest mesh --halfedges draws")
      ->capture_default_str()
      ->transform(whole_number<std::size_t>(1));
  // Command-line mistakes are usage errors (exit 2), found while parsing.
  app->parse_complete_callback([o] {
    if (o->input.empty() == o->grid.empty())
      throw CLI::ValidationError("render", "give one mesh file, or several after --grid");
    if (o->eye.empty() != o->target.empty())
      throw CLI::ValidationError("render", "--eye and --target go together");
    if (o->halfedges && !o->grid.empty())
      throw CLI::ValidationError("render", "--halfedges draws one mesh; --grid is for shaded pictures");
  });
}

}  // namespace

const CommandBinder render_command = bind_command<RenderCommandOptions, add_render_arguments, run_render>;

}  // namespace hedge::cli
