// hedge tour FILE: the library's stages on one mesh, as pictures. It loads (repairing), validates,
// edits and draws each stage, writes the edited meshes and a contact sheet of every stage to the
// output folder, and prints a table of counts and timings. `./run` runs it on the shipped sample.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "commands.h"
#include "hedge/algorithms/decimate.h"
#include "hedge/algorithms/detach_faces.h"
#include "hedge/algorithms/fill_hole.h"
#include "hedge/algorithms/fracture.h"
#include "hedge/algorithms/fracture_solid.h"
#include "hedge/algorithms/smooth.h"
#include "hedge/algorithms/split_all_faces.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/core/build.h"
#include "hedge/core/export.h"
#include "hedge/core/operations.h"
#include "hedge/error.h"
#include "load.h"
#include "memory_budget.h"
#include "mesh_stats.h"
#include "numbers.h"
#include "picture/diagram.h"
#include "picture/raster.h"
#include "picture/sheet.h"
#include "progress_bar.h"

namespace hedge::cli {

namespace {

using namespace hedge::picture;
using Clock = std::chrono::steady_clock;

struct TourOptions {
  std::string input;
  std::string out_dir = "out";
  int panel = 360;
  //! The subdivision stages are skipped where their result would pass this many faces, so that the
  //! tour of a large mesh stays quick and small.
  std::size_t max_faces = 4'000'000;
  LoadOptions load;
  //! Stages whose subdivision is estimated to need more memory are skipped too.
};

struct Row {
  std::string stage;
  std::size_t vertices, faces, boundary_loops;
  bool valid;
  double edit_ms, draw_ms;
  std::string file;
};

//! One piece of an exploded view: its mesh and the point it is pushed away from the impact by.
struct ViewPiece {
  const SurfaceMesh* mesh;
  Vec3d centroid;
};

//! The remaining mesh and the pieces (shards, or solid pieces) as one mesh for a picture, each
//! piece pushed away from the impact by `spread` times its centroid's distance, so the cracks show.
//! The cut faces of a solid fracture keep their mark ("f:inner"), for the picture's inner colour.
SurfaceMesh exploded_view(const SurfaceMesh& rest, const std::vector<ViewPiece>& pieces, const Vec3& impact,
                          double spread) {
  ExportOptions plain;
  plain.corner_attributes = false;
  // Every face's size spelled out, so triangles and polygons of the pieces can be mixed.
  auto sizes = [](const IndexedMesh& m) {
    return m.face_sizes.empty() ? std::vector<std::uint32_t>(m.indices.size() / 3, 3) : m.face_sizes;
  };
  std::vector<std::uint8_t> inner;  // per face of `all`, in order
  auto add_inner = [&](const SurfaceMesh& m) {
    const auto mark = m.get_face_property<std::uint8_t>(kInnerProperty);
    for (Face f : m.faces()) inner.push_back(mark ? mark[f] : 0);
  };
  IndexedMesh all = to_indexed(rest, plain);
  all.face_sizes = sizes(all);
  // The pieces' faces are appended without submeshes: the picture needs only "f:inner", and
  // face_submeshes must hold one per face or none.
  all.face_submeshes.clear();
  add_inner(rest);
  for (const ViewPiece& v : pieces) {
    const IndexedMesh piece = to_indexed(*v.mesh, plain);
    const Vec3 push{float(spread * (v.centroid.x - impact.x)), float(spread * (v.centroid.y - impact.y)),
                    float(spread * (v.centroid.z - impact.z))};
    const auto base = static_cast<std::uint32_t>(all.positions.size());
    for (const Vec3& p : piece.positions) all.positions.push_back({p.x + push.x, p.y + push.y, p.z + push.z});
    for (std::uint32_t i : piece.indices) all.indices.push_back(base + i);
    const std::vector<std::uint32_t> piece_sizes = sizes(piece);
    all.face_sizes.insert(all.face_sizes.end(), piece_sizes.begin(), piece_sizes.end());
    add_inner(*v.mesh);
  }
  BuildOptions exact;
  exact.weld = Weld::none;
  SurfaceMesh view = build(all, exact);
  // The faces come out in the order they went in, unless the build dropped some.
  if (view.n_faces() == inner.size() &&
      std::find(inner.begin(), inner.end(), std::uint8_t(1)) != inner.end()) {
    auto mark = view.add_face_property<std::uint8_t>(kInnerProperty, 0);
    std::size_t i = 0;
    for (Face f : view.faces()) mark[f] = inner[i++];
  }
  return view;
}

//! The interior vertex nearest to the eye, so that an edit around it faces the camera.
Vertex front_vertex(const SurfaceMesh& m, const Camera& camera) {
  Vertex best;
  double best_d = 1e300;
  for (Vertex v : m.vertices()) {
    if (m.is_boundary(v) || m.is_isolated(v)) continue;
    const Vec3d d = to_double(m.position(v)) - camera.eye;
    const double dd = dot(d, d);
    if (dd < best_d) best_d = dd, best = v;
  }
  return best;
}

// The faces within `rings` rings of v, sorted.
std::vector<Face> faces_near(const SurfaceMesh& m, Vertex v, int rings) {
  std::vector<Vertex> frontier{v}, seen{v};
  std::vector<Face> faces;
  for (int r = 0; r < rings; ++r) {
    std::vector<Vertex> next;
    for (Vertex u : frontier)
      for (Face f : m.faces(u)) {
        if (!f.is_valid() || std::find(faces.begin(), faces.end(), f) != faces.end()) continue;
        faces.push_back(f);
        for (Vertex w : m.vertices(f))
          if (std::find(seen.begin(), seen.end(), w) == seen.end()) {
            seen.push_back(w);
            next.push_back(w);
          }
      }
    frontier = std::move(next);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

//! What the stages of a tour share: the loaded mesh, the camera, the meshes made so far, and the
//! pictures and table rows they added.
struct Tour {
  explicit Tour(const TourOptions& options) : o(options) {}

  const TourOptions& o;
  LoadedMesh loaded;
  double load_ms = 0;
  int w = 0, h = 0;
  Camera camera;
  std::string base;  //!< output folder and mesh name, the start of every file written
  std::uint64_t budget = 0;
  std::size_t corners = 0;  //!< face corners of the loaded mesh: faces after one 1-to-n split
  std::string too_large;    //!< why a subdivision stage is skipped
  SurfaceMesh split;        //!< all faces split 1-to-3, else the loaded mesh
  bool split_fits = false;
  std::optional<SurfaceMesh> fine;  //!< the finest triangle mesh so far, for decimation and fracture
  std::vector<Panel> panels;
  std::vector<Row> rows;
  std::vector<std::pair<std::string, std::string>> skipped;  //!< stage, why

  const SurfaceMesh& mesh() const { return loaded.mesh; }

  //! Draws `m` as the panel `stage`, adds its row, and writes it to `file` unless that is empty.
  void add(const std::string& stage, const SurfaceMesh& m, double edit_ms, RenderOptions r,
           const std::string& file) {
    r.width = w;
    r.height = h;
    const auto d = Clock::now();
    panels.push_back({render(m, camera, r), stage});
    add_row(stage, m, edit_ms, ms_since(d), file);
  }

  void add_row(const std::string& stage, const SurfaceMesh& m, double edit_ms, double draw_ms,
               const std::string& file) {
    const MeshStats s = compute_stats(m);
    rows.push_back(
        {stage, s.vertices, s.faces, s.boundary_loops, s.problems.empty(), edit_ms, draw_ms, file});
    if (!file.empty()) write_mesh(m, file);
  }
};

//! Runs `edit` and returns how long it took, in milliseconds.
template <typename Edit>
double timed(Edit&& edit) {
  const auto t = Clock::now();
  edit();
  return ms_since(t);
}

RenderOptions wireframe() {
  RenderOptions r;
  r.wireframe = true;
  return r;
}

// 1. As loaded: repaired vertices as dots, boundaries and creases in colour.
void stage_loaded(Tour& t) {
  RenderOptions r;
  r.feature_angle = 60;
  const BuildReport& report = t.loaded.report;
  std::unordered_map<Index, int> uses;
  for (Index origin : report.vertex_origin) ++uses[origin];
  for (std::size_t v = 0; v < report.vertex_origin.size(); ++v)
    if (uses[report.vertex_origin[v]] > 1) r.marked.push_back(Vertex(Index(v)));
  const std::string what =
      report.repairs() > 0 ? "loaded, " + std::to_string(report.repairs()) + " repairs" : "loaded";
  t.add(what, t.mesh(), t.load_ms, r, "");
}

// 2. The structure: every edge, vertices coloured by valence.
void stage_edges(Tour& t) {
  RenderOptions r = wireframe();
  r.color_by = ColorBy::valence;
  t.add("edges, valence colours", t.mesh(), 0, r, "");
}

// 3. Catmull-Clark: any polygons become quads, and the surface rounds off. Two steps, fewer on a
// large mesh (a step makes as many quads as there are face corners).
void stage_catmull_clark(Tour& t) {
  const std::size_t max_faces = t.o.max_faces;
  int steps = t.corners * 4 <= max_faces ? 2 : t.corners <= max_faces ? 1 : 0;
  while (steps > 0 && subdivide_memory(t.mesh(), Subdivision::catmull_clark, steps) > t.budget) --steps;
  if (steps == 0) {
    t.skipped.push_back({"Catmull-Clark", t.too_large});
    return;
  }
  SurfaceMesh cc = t.mesh();
  const double ms = timed([&] { subdivide(cc, Subdivision::catmull_clark, steps); });
  t.add("Catmull-Clark, " + std::to_string(steps) + (steps == 1 ? " step" : " steps"), cc, ms, wireframe(),
        t.base + "_catmull_clark.obj");
}

// 4. Split all faces 1-to-3 at their centroids (a triangle per corner).
void stage_split(Tour& t) {
  t.split = t.mesh();
  t.split_fits =
      t.corners <= t.o.max_faces && subdivide_memory(t.mesh(), Subdivision::split_faces, 1) <= t.budget;
  if (!t.split_fits) {
    t.skipped.push_back({"split all faces", t.too_large});
    return;
  }
  const double ms = timed([&] { split_all_faces(t.split); });
  RenderOptions r = wireframe();
  r.shading = Shading::flat;
  t.add("split all faces (1-to-3)", t.split, ms, r, t.base + "_split.obj");
}

// 5. The split mesh through one step of Loop's subdivision.
void stage_loop(Tour& t) {
  if (!t.split_fits || 4 * t.split.n_faces() > t.o.max_faces ||
      subdivide_memory(t.split, Subdivision::loop, 1) > t.budget) {
    t.skipped.push_back({"Loop subdivision", t.too_large});
    if (t.split_fits) t.fine = t.split;
    return;
  }
  SurfaceMesh loop = t.split;
  const double ms = timed([&] { subdivide(loop, Subdivision::loop, 1); });
  t.add("then Loop subdivision", loop, ms, wireframe(), t.base + "_loop.obj");
  t.fine = std::move(loop);
}

// 6. The split mesh smoothed instead by Taubin's filter, which does not shrink it. A mesh too large
// to split is smoothed as it is.
void stage_smooth(Tour& t) {
  SmoothOptions taubin;
  taubin.method = SmoothMethod::taubin;
  const double ms = timed([&] { smooth(t.split, taubin); });
  t.add(t.split_fits ? "or smoothed (Taubin, 10 iterations)" : "smoothed (Taubin, 10 iterations)", t.split,
        ms, wireframe(), t.base + "_smooth.obj");
}

// 7. The finest triangle mesh decimated to a quarter of its faces by quadric error.
void stage_decimate(Tour& t) {
  if (!t.fine) {
    t.skipped.push_back({"decimation and fracture", "no triangle mesh: for the split, " + t.too_large});
    return;
  }
  SurfaceMesh coarse = *t.fine;
  DecimateOptions d;
  d.target_faces = std::max<std::size_t>(4, t.fine->n_faces() / 4);
  DecimateResult dr;
  const double ms = timed([&] { dr = decimate(coarse, d); });
  t.add("decimated to " + std::to_string(dr.faces) + " faces", coarse, ms, wireframe(),
        t.base + "_decimated.obj");
}

// 8. The finest triangle mesh broken like glass where it faces the eye, its shards pushed apart so
// the cracks show.
void stage_fracture(Tour& t) {
  if (!t.fine) return;  // said by stage_decimate
  const Vertex hit = front_vertex(*t.fine, t.camera);
  if (!hit.is_valid()) {
    t.skipped.push_back({"fracture", "no vertex faces the camera"});
    return;
  }
  SurfaceMesh rest = *t.fine;
  FractureOptions f;
  f.seed = 1;
  try {
    FractureResult fr;
    const double ms = timed([&] { fr = fracture(rest, t.fine->position(hit), f); });
    RenderOptions r;
    r.color_by = ColorBy::shard;
    r.shading = Shading::flat;
    std::vector<ViewPiece> pieces;
    for (const Shard& shard : fr.shards) pieces.push_back({&shard.mesh, shard.centroid});
    const SurfaceMesh view = exploded_view(rest, pieces, fr.impact_point, 0.35);
    t.add("glass fracture: " + std::to_string(fr.shards.size()) + " shards", view, ms, r,
          t.base + "_fractured.obj");
  } catch (const InvalidInputError& e) {
    // A mesh too small to break, say: the tour goes on, and says why.
    t.skipped.push_back({"fracture", e.what()});
  }
}

// 9. The mesh, if closed, broken as a solid where it faces the eye: closed pieces pushed apart from
// the impact, their cut faces in the inner colour. The finest triangle mesh when there is one.
void stage_solid_fracture(Tour& t) {
  const SurfaceMesh& whole = t.fine ? *t.fine : t.mesh();
  const Vertex hit = front_vertex(whole, t.camera);
  if (!hit.is_valid()) {
    t.skipped.push_back({"solid fracture", "no vertex faces the camera"});
    return;
  }
  SurfaceMesh rest = whole;
  SolidFractureOptions f;
  f.material = fracture_material("ice");
  f.radius_fraction = 0.22;
  f.seed = 1;
  // Refused on an open mesh, say: the tour goes on, and says why.
  const std::string why = solid_fracture_refusal(rest, whole.position(hit), f);
  if (!why.empty()) {
    t.skipped.push_back({"solid fracture", why});
    return;
  }
  try {
    SolidFractureResult sr;
    const double ms = timed([&] { sr = fracture_solid(rest, whole.position(hit), f); });
    std::vector<ViewPiece> pieces;
    for (const SolidPiece& p : sr.pieces) pieces.push_back({&p.mesh, p.centroid});
    RenderOptions r;
    r.color_by = ColorBy::shard;
    r.shading = Shading::flat;
    const SurfaceMesh view = exploded_view(rest, pieces, sr.impact_point, 0.5);
    t.add("solid fracture: " + std::to_string(sr.pieces.size()) + " pieces", view, ms, r,
          t.base + "_solid_fractured.obj");
  } catch (const InvalidInputError& e) {
    t.skipped.push_back({"solid fracture", e.what()});
  }
}

//! Rings of faces around `centre` until they are about a sixtieth of the mesh, keeping at least
//! half of it.
std::vector<Face> hole_region(const SurfaceMesh& mesh, Vertex centre) {
  int rings = 1;
  std::vector<Face> region = faces_near(mesh, centre, rings);
  while (region.size() < std::max<std::size_t>(4, mesh.n_faces() / 60) && rings < 12) {
    std::vector<Face> wider = faces_near(mesh, centre, rings + 1);
    if (2 * wider.size() > mesh.n_faces()) break;
    region = std::move(wider);
    ++rings;
  }
  return region;
}

//! Fills the boundary loops of `filled` that `original` does not have; returns the faces added.
std::size_t fill_new_holes(SurfaceMesh& filled, const SurfaceMesh& original) {
  std::size_t faces = 0;
  const std::size_t loops_before = original.boundary_loops().size();
  for (int guard = 0; filled.boundary_loops().size() > loops_before && guard < 64; ++guard) {
    // Fill the loops the cut made: those with a half-edge of a face next to the region.
    bool any = false;
    for (Halfedge b : filled.boundary_loops()) {
      if (!original.is_boundary(b) && can_fill_hole(filled, b)) {
        faces += fill_hole(filled, b).size();
        any = true;
        break;
      }
    }
    if (!any) break;
  }
  return faces;
}

// 10. A hole cut around the vertex nearest the eye, then 11. filled again, and 12. the half-edge
// diagram of the faces around that vertex, detached as a mesh of their own.
void stage_hole(Tour& t) {
  const SurfaceMesh& mesh = t.mesh();
  const Vertex centre = front_vertex(mesh, t.camera);
  if (!centre.is_valid() || faces_near(mesh, centre, 1).size() >= mesh.n_faces()) return;
  SurfaceMesh holed = mesh;
  const std::vector<Face> region = hole_region(mesh, centre);
  const double cut_ms = timed([&] { remove_faces(holed, region); });
  t.add("faces removed: a hole", holed, cut_ms, wireframe(), t.base + "_hole.obj");

  SurfaceMesh filled = holed;
  std::size_t filled_faces = 0;
  const double fill_ms = timed([&] { filled_faces = fill_new_holes(filled, mesh); });
  RenderOptions f = wireframe();
  f.color_by = ColorBy::face;
  f.shading = Shading::flat;
  t.add("hole filled: " + std::to_string(filled_faces) + " new faces", filled, fill_ms, f,
        t.base + "_filled.obj");

  SurfaceMesh rest = mesh, patch;
  const double detach_ms = timed([&] { patch = detach_faces(rest, faces_near(mesh, centre, 1)); });
  Image diagram(t.w, t.h);
  ImageCanvas canvas(diagram);
  DiagramOptions d;
  d.legend = false;
  const double draw_ms =
      timed([&] { draw_halfedge_diagram(patch, diagram_camera(patch, double(t.w) / t.h), canvas, d); });
  t.panels.push_back({std::move(diagram), "half-edges of one vertex's faces"});
  t.add_row("detached one-ring (diagram)", patch, detach_ms, draw_ms, t.base + "_patch.obj");
}

//! The stages of the tour, in order; each adds pictures and rows, or says why it was skipped.
constexpr void (*kStages[])(Tour&) = {stage_loaded,         stage_edges,  stage_catmull_clark, stage_split,
                                      stage_loop,           stage_smooth, stage_decimate,      stage_fracture,
                                      stage_solid_fracture, stage_hole};

//! Prints the table of stages and what was written; true when every stage's mesh was valid.
bool print_report(const Tour& t, const std::string& sheet_path) {
  std::printf("%-34s %9s %9s %6s %6s %9s %9s\n", "stage", "vertices", "faces", "holes", "valid", "edit ms",
              "draw ms");
  bool all_valid = true;
  for (const Row& r : t.rows) {
    std::printf("%-34s %9zu %9zu %6zu %6s %9.2f %9.1f\n", r.stage.c_str(), r.vertices, r.faces,
                r.boundary_loops, r.valid ? "yes" : "NO", r.edit_ms, r.draw_ms);
    all_valid = all_valid && r.valid;
  }
  for (const auto& [stage, why] : t.skipped) std::printf("%-34s skipped: %s\n", stage.c_str(), why.c_str());
  std::printf("\nwrote %s (every stage side by side)\n", sheet_path.c_str());
  for (const Row& r : t.rows)
    if (!r.file.empty()) std::printf("wrote %s\n", r.file.c_str());
  return all_valid;
}

int run_tour(const TourOptions& o) {
  const auto total = Clock::now();
  std::filesystem::create_directories(o.out_dir);
  std::string name = std::filesystem::path(o.input).stem().string();
  if (name.empty()) name = "mesh";

  Tour t(o);
  t.base = (std::filesystem::path(o.out_dir) / name).string();
  t.load_ms = timed([&] { t.loaded = load_mesh(o.input, o.load); });
  if (t.mesh().n_faces() == 0) throw InvalidInputError(o.input + ": nothing to show: the mesh has no faces");
  t.w = o.panel;
  t.h = o.panel * 3 / 4;
  t.camera = frame(t.mesh(), View::iso, double(t.w) / t.h);
  for (Face f : t.mesh().faces()) t.corners += t.mesh().valence(f);
  t.budget = effective_budget(o.load.memory);
  t.too_large = "the result would pass " + std::to_string(o.max_faces) + " faces or " +
                bytes_text(double(t.budget)) + " of memory (--max-faces, --max-memory)";
  for (auto stage : kStages) stage(t);

  const std::string sheet_path = t.base + "_tour.png";
  write_png(contact_sheet(t.panels, 3), sheet_path);
  const bool all_valid = print_report(t, sheet_path);
  std::printf("total %.0f ms\n", ms_since(total));
  return all_valid ? kExitOk : kExitDataError;
}

void add_tour_arguments(CLI::App* app, TourOptions* o) {
  add_mesh_file_argument(*app, o->input);
  app->add_option("--out", o->out_dir, "Folder for the pictures and meshes (created if missing)")
      ->capture_default_str();
  app->add_option("--panel", o->panel, "Width of each picture of the contact sheet, in pixels")
      ->capture_default_str()
      ->transform(whole_number<int>(64, 2048));
  app->add_option("--max-faces", o->max_faces,
                  "Skip the subdivision stages whose result would pass this many faces")
      ->capture_default_str()
      ->transform(whole_number<std::size_t>(1));
}

}  // namespace

const CommandBinder tour_command = bind_command<TourOptions, add_tour_arguments, run_tour>;

}  // namespace hedge::cli
