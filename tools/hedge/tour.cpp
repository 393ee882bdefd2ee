// hedge tour FILE: the library's stages on one mesh, as pictures. It loads (repairing), validates,
// edits and draws each stage, writes the edited meshes and a contact sheet of every stage to the
// output folder, and prints a table of counts and timings. `./run` runs it on the shipped sample.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "commands.h"
#include "hedge/algorithms/decimate.h"
#include "hedge/algorithms/detach_faces.h"
#include "hedge/algorithms/fill_hole.h"
#include "hedge/algorithms/fracture.h"
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

double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

// The interior vertex nearest to the eye, so that an edit around it faces the camera.
//! The remaining mesh and its shards as one mesh for a picture, each shard pushed away from the
//! impact by `spread` times its centroid's distance, so the cracks show.
SurfaceMesh exploded_view(const SurfaceMesh& rest, const std::vector<Shard>& shards, const Vec3& impact,
                          double spread) {
  ExportOptions plain;
  plain.corner_attributes = false;
  // Every face's size spelled out, so triangles and polygons of the pieces can be mixed.
  auto sizes = [](const IndexedMesh& m) {
    return m.face_sizes.empty() ? std::vector<std::uint32_t>(m.indices.size() / 3, 3) : m.face_sizes;
  };
  IndexedMesh all = to_indexed(rest, plain);
  all.face_sizes = sizes(all);
  for (const Shard& s : shards) {
    const IndexedMesh piece = to_indexed(s.mesh, plain);
    const Vec3 push{float(spread * (s.centroid.x - impact.x)), float(spread * (s.centroid.y - impact.y)),
                    float(spread * (s.centroid.z - impact.z))};
    const auto base = static_cast<std::uint32_t>(all.positions.size());
    for (const Vec3& p : piece.positions) all.positions.push_back({p.x + push.x, p.y + push.y, p.z + push.z});
    for (std::uint32_t i : piece.indices) all.indices.push_back(base + i);
    const std::vector<std::uint32_t> piece_sizes = sizes(piece);
    all.face_sizes.insert(all.face_sizes.end(), piece_sizes.begin(), piece_sizes.end());
  }
  BuildOptions exact;
  exact.weld = Weld::none;
  return build(all, exact);
}

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

int run_tour(const TourOptions& o) {
  const auto total = Clock::now();
  std::filesystem::create_directories(o.out_dir);
  std::string name = std::filesystem::path(o.input).stem().string();
  if (name.empty()) name = "mesh";
  const std::string base = (std::filesystem::path(o.out_dir) / name).string();

  auto t = Clock::now();
  LoadedMesh loaded = load_mesh(o.input, o.load);
  const double load_ms = ms_since(t);
  SurfaceMesh& mesh = loaded.mesh;
  if (mesh.n_faces() == 0) throw InvalidInputError(o.input + ": nothing to show: the mesh has no faces");

  const int w = o.panel, h = o.panel * 3 / 4;
  const Camera camera = frame(mesh, View::iso, double(w) / h);
  std::vector<Panel> panels;
  std::vector<Row> rows;
  std::vector<std::pair<std::string, std::string>> skipped;  // stage, why
  auto add = [&](const std::string& stage, const SurfaceMesh& m, double edit_ms, RenderOptions r,
                 const std::string& file) {
    r.width = w;
    r.height = h;
    const auto d = Clock::now();
    panels.push_back({render(m, camera, r), stage});
    const double draw_ms = ms_since(d);
    const MeshStats s = compute_stats(m);
    rows.push_back(
        {stage, s.vertices, s.faces, s.boundary_loops, s.problems.empty(), edit_ms, draw_ms, file});
    if (!file.empty()) write_mesh(m, file);
  };

  // 1. As loaded: repaired vertices as dots, boundaries and creases in colour.
  {
    RenderOptions r;
    r.feature_angle = 60;
    std::unordered_map<Index, int> uses;
    for (Index origin : loaded.report.vertex_origin) ++uses[origin];
    for (std::size_t v = 0; v < loaded.report.vertex_origin.size(); ++v)
      if (uses[loaded.report.vertex_origin[v]] > 1) r.marked.push_back(Vertex(Index(v)));
    const std::string what = loaded.report.repairs() > 0
                                 ? "loaded, " + std::to_string(loaded.report.repairs()) + " repairs"
                                 : "loaded";
    add(what, mesh, load_ms, r, "");
  }
  // 2. The structure: every edge, vertices coloured by valence.
  {
    RenderOptions r;
    r.wireframe = true;
    r.color_by = ColorBy::valence;
    add("edges, valence colours", mesh, 0, r, "");
  }
  // 3. Catmull-Clark: any polygons become quads, and the surface rounds off. Two steps, fewer on a
  // large mesh (a step makes as many quads as there are face corners).
  std::size_t corners = 0;
  for (Face f : mesh.faces()) corners += mesh.valence(f);
  const std::uint64_t budget = effective_budget(o.load.memory);
  const std::string too_large = "the result would pass " + std::to_string(o.max_faces) + " faces or " +
                                bytes_text(double(budget)) + " of memory (--max-faces, --max-memory)";
  int cc_steps = corners * 4 <= o.max_faces ? 2 : corners <= o.max_faces ? 1 : 0;
  while (cc_steps > 0 && subdivide_memory(mesh, Subdivision::catmull_clark, cc_steps) > budget) --cc_steps;
  if (cc_steps > 0) {
    SurfaceMesh cc = mesh;
    t = Clock::now();
    subdivide(cc, Subdivision::catmull_clark, cc_steps);
    const double ms = ms_since(t);
    RenderOptions r;
    r.wireframe = true;
    add("Catmull-Clark, " + std::to_string(cc_steps) + (cc_steps == 1 ? " step" : " steps"), cc, ms, r,
        base + "_catmull_clark.obj");
  } else {
    skipped.push_back({"Catmull-Clark", too_large});
  }
  // 4. Split all faces 1-to-3 at their centroids (a triangle per corner), 5. the result through one
  // step of Loop's subdivision, and 6. smoothed instead by Taubin's filter, which does not shrink
  // it. A mesh too large to split is smoothed as it is.
  SurfaceMesh split = mesh;
  std::optional<SurfaceMesh> fine;  // the finest triangle mesh so far, for decimation and fracture
  const bool split_fits =
      corners <= o.max_faces && subdivide_memory(mesh, Subdivision::split_faces, 1) <= budget;
  if (split_fits) {
    t = Clock::now();
    split_all_faces(split);
    const double ms = ms_since(t);
    RenderOptions r;
    r.wireframe = true;
    r.shading = Shading::flat;
    add("split all faces (1-to-3)", split, ms, r, base + "_split.obj");
  } else {
    skipped.push_back({"split all faces", too_large});
  }
  if (split_fits && 4 * split.n_faces() <= o.max_faces &&
      subdivide_memory(split, Subdivision::loop, 1) <= budget) {
    SurfaceMesh loop = split;
    t = Clock::now();
    subdivide(loop, Subdivision::loop, 1);
    const double loop_ms = ms_since(t);
    RenderOptions lr;
    lr.wireframe = true;
    add("then Loop subdivision", loop, loop_ms, lr, base + "_loop.obj");
    fine = std::move(loop);
  } else {
    skipped.push_back({"Loop subdivision", too_large});
    if (split_fits) fine = split;
  }
  {
    t = Clock::now();
    SmoothOptions taubin;
    taubin.method = SmoothMethod::taubin;
    smooth(split, taubin);
    const double smooth_ms = ms_since(t);
    RenderOptions sr;
    sr.wireframe = true;
    add(split_fits ? "or smoothed (Taubin, 10 iterations)" : "smoothed (Taubin, 10 iterations)", split,
        smooth_ms, sr, base + "_smooth.obj");
  }
  // 7. The finest triangle mesh decimated to a quarter of its faces by quadric error, and 8. broken
  // like glass where it faces the eye, its shards pushed apart so the cracks show.
  if (fine) {
    SurfaceMesh coarse = *fine;
    DecimateOptions d;
    d.target_faces = std::max<std::size_t>(4, fine->n_faces() / 4);
    t = Clock::now();
    const DecimateResult dr = decimate(coarse, d);
    const double decimate_ms = ms_since(t);
    RenderOptions r;
    r.wireframe = true;
    add("decimated to " + std::to_string(dr.faces) + " faces", coarse, decimate_ms, r,
        base + "_decimated.obj");

    const Vertex hit = front_vertex(*fine, camera);
    if (hit.is_valid()) {
      SurfaceMesh rest = *fine;
      FractureOptions f;
      f.seed = 1;
      t = Clock::now();
      try {
        const FractureResult fr = fracture(rest, fine->position(hit), f);
        const double fracture_ms = ms_since(t);
        RenderOptions fo;
        fo.color_by = ColorBy::shard;
        fo.shading = Shading::flat;
        const SurfaceMesh view = exploded_view(rest, fr.shards, fr.impact_point, 0.35);
        add("glass fracture: " + std::to_string(fr.shards.size()) + " shards", view, fracture_ms, fo,
            base + "_fractured.obj");
      } catch (const InvalidInputError& e) {
        // A mesh too small to break, say: the tour goes on, and says why.
        skipped.push_back({"fracture", e.what()});
      }
    } else {
      skipped.push_back({"fracture", "no vertex faces the camera"});
    }
  } else {
    skipped.push_back({"decimation and fracture", "no triangle mesh: for the split, " + too_large});
  }
  // 9. A hole cut around the vertex nearest the eye, then 10. filled again.
  const Vertex centre = front_vertex(mesh, camera);
  if (centre.is_valid() && faces_near(mesh, centre, 1).size() < mesh.n_faces()) {
    // Rings around it until the hole is about a sixtieth of the mesh, keeping at least half.
    int rings = 1;
    std::vector<Face> region = faces_near(mesh, centre, rings);
    while (region.size() < std::max<std::size_t>(4, mesh.n_faces() / 60) && rings < 12) {
      std::vector<Face> wider = faces_near(mesh, centre, rings + 1);
      if (2 * wider.size() > mesh.n_faces()) break;
      region = std::move(wider);
      ++rings;
    }
    SurfaceMesh holed = mesh;
    t = Clock::now();
    remove_faces(holed, region);
    const double cut_ms = ms_since(t);
    RenderOptions r;
    r.wireframe = true;
    add("faces removed: a hole", holed, cut_ms, r, base + "_hole.obj");

    SurfaceMesh filled = holed;
    t = Clock::now();
    std::size_t filled_faces = 0;
    const std::size_t loops_before = mesh.boundary_loops().size();
    for (int guard = 0; filled.boundary_loops().size() > loops_before && guard < 64; ++guard) {
      // Fill the loops the cut made: those with a half-edge of a face next to the region.
      bool any = false;
      for (Halfedge b : filled.boundary_loops()) {
        if (!mesh.is_boundary(b) && can_fill_hole(filled, b)) {
          filled_faces += fill_hole(filled, b).size();
          any = true;
          break;
        }
      }
      if (!any) break;
    }
    const double fill_ms = ms_since(t);
    RenderOptions f;
    f.wireframe = true;
    f.color_by = ColorBy::face;
    f.shading = Shading::flat;
    add("hole filled: " + std::to_string(filled_faces) + " new faces", filled, fill_ms, f,
        base + "_filled.obj");

    // 11. The half-edge diagram of the faces around that vertex, detached as a mesh of their own.
    SurfaceMesh rest = mesh;
    t = Clock::now();
    const SurfaceMesh patch = detach_faces(rest, faces_near(mesh, centre, 1));
    const double detach_ms = ms_since(t);
    Image diagram(w, h);
    ImageCanvas canvas(diagram);
    DiagramOptions d;
    d.legend = false;
    const auto dt = Clock::now();
    draw_halfedge_diagram(patch, diagram_camera(patch, double(w) / h), canvas, d);
    const double draw_ms = ms_since(dt);
    panels.push_back({std::move(diagram), "half-edges of one vertex's faces"});
    const MeshStats s = compute_stats(patch);
    rows.push_back({"detached one-ring (diagram)", s.vertices, s.faces, s.boundary_loops, s.problems.empty(),
                    detach_ms, draw_ms, base + "_patch.obj"});
    write_mesh(patch, base + "_patch.obj");
  }

  const std::string sheet_path = base + "_tour.png";
  write_png(contact_sheet(panels, 3), sheet_path);

  std::printf("%-34s %9s %9s %6s %6s %9s %9s\n", "stage", "vertices", "faces", "holes", "valid", "edit ms",
              "draw ms");
  bool all_valid = true;
  for (const Row& r : rows) {
    std::printf("%-34s %9zu %9zu %6zu %6s %9.2f %9.1f\n", r.stage.c_str(), r.vertices, r.faces,
                r.boundary_loops, r.valid ? "yes" : "NO", r.edit_ms, r.draw_ms);
    all_valid = all_valid && r.valid;
  }
  for (const auto& [stage, why] : skipped) std::printf("%-34s skipped: %s\n", stage.c_str(), why.c_str());
  std::printf("\nwrote %s (every stage side by side)\n", sheet_path.c_str());
  for (const Row& r : rows)
    if (!r.file.empty()) std::printf("wrote %s\n", r.file.c_str());
  std::printf("total %.0f ms\n", ms_since(total));
  return all_valid ? kExitOk : kExitDataError;
}

}  // namespace

Command add_tour_command(CLI::App& parent) {
  auto o = std::make_shared<TourOptions>();
  CLI::App* app = parent.add_subcommand(
      "tour",
      "Show what hedge does to a mesh: load and repair, validate, Catmull-Clark, split all faces, "
      "Loop-subdivide and smooth, decimate, break like glass, "
      "cut a hole and fill it, the half-edge diagram of one vertex's faces; writes a contact sheet PNG of "
      "every stage, the "
      "edited meshes, and prints counts and timings");
  app->add_option("FILE", o->input, "Mesh file (.obj, .off, .ply, .stl, .gltf, .glb)")->required();
  app->add_option("--out", o->out_dir, "Folder for the pictures and meshes (created if missing)")
      ->capture_default_str();
  app->add_option("--panel", o->panel, "Width of each picture of the contact sheet, in pixels")
      ->capture_default_str()
      ->transform(whole_number<int>(64, 2048));
  app->add_option("--max-faces", o->max_faces,
                  "Skip the subdivision stages whose result would pass this many faces")
      ->capture_default_str()
      ->transform(whole_number<std::size_t>(1));
  add_load_options(*app, o->load);
  return {app, [o] { return run_tour(*o); }};
}

}  // namespace hedge::cli
