// hedge decimate IN OUT: read, decimate by quadric-ranked edge collapses, write; formats by extension.
#include "hedge/algorithms/decimate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>

#include "commands.h"
#include "hedge/error.h"
#include "load.h"
#include "numbers.h"
#include "progress_bar.h"

namespace hedge::cli {

namespace {

struct DecimateCommandOptions : InOutOptions {
  double ratio = 0;  // 0: not given
  std::size_t faces = 0, vertices = 0;
  double max_error = std::numeric_limits<double>::infinity();
  double boundary_weight = DecimateOptions{}.boundary_weight;
  double feature_angle = DecimateOptions{}.feature_angle_degrees;
  double feature_weight = DecimateOptions{}.feature_weight;
  double attribute_weight = 0;
  double max_normal_change = DecimateOptions{}.max_normal_change_degrees;
  bool normal_change_given = false;  // then it holds to the end (DecimateOptions::relax_normal_change)
  bool keep_boundary = false;
  bool break_seams = false;
};

int run_decimate(const DecimateCommandOptions& o) {
  LoadedMesh loaded = load_input(o);
  SurfaceMesh& mesh = loaded.mesh;
  DecimateOptions d;
  if (o.ratio > 0)
    d.target_vertices =
        std::max<std::size_t>(1, std::size_t(std::llround(o.ratio * double(mesh.n_vertices()))));
  if (o.vertices > 0) d.target_vertices = o.vertices;
  d.target_faces = o.faces;
  d.max_error = o.max_error;
  d.boundary_weight = o.boundary_weight;
  d.feature_angle_degrees = o.feature_angle;
  d.feature_weight = o.feature_weight;
  d.attribute_weight = o.attribute_weight;
  d.max_normal_change_degrees = o.max_normal_change;
  d.relax_normal_change = !o.normal_change_given;
  d.keep_boundary = o.keep_boundary;
  d.keep_seams = !o.break_seams;
  const std::size_t v0 = mesh.n_vertices(), f0 = mesh.n_faces();
  DecimateResult r;
  const double ms = run_with_progress("decimate", [&](Progress progress) {
    d.progress = std::move(progress);
    r = decimate(mesh, d);
  });
  save_mesh(mesh, o.output, o.ascii);
  std::printf(
      "decimated %s -> %s: %zu -> %zu vertices, %zu -> %zu faces, %zu collapses, max error %.6g, %.1f ms\n",
      o.input.c_str(), o.output.c_str(), v0, r.vertices, f0, r.faces, r.collapses, r.max_error, ms);
  return kExitOk;
}

void add_decimate_arguments(CLI::App* app, DecimateCommandOptions* o) {
  add_in_out_arguments(*app, o->input, o->output, "Input mesh file (triangles)");
  auto* ratio = app->add_option("--ratio", o->ratio, "Keep this fraction of the vertices, in (0, 1]")
                    ->transform(real_number(0, 1, true));
  auto* faces = app->add_option("--faces", o->faces, "Stop at this many faces")
                    ->transform(whole_number<std::size_t>(1));
  auto* vertices = app->add_option("--vertices", o->vertices, "Stop at this many vertices")
                       ->transform(whole_number<std::size_t>(1));
  ratio->excludes(vertices);
  app->add_option(
         "--max-error", o->max_error,
         "Stop before a collapse that would move the surface by more than this distance (model units)")
      ->transform(real_number(0));
  add_real_option(*app, "--boundary-weight", o->boundary_weight,
                  "Weight of the planes that keep open boundaries (0: none)", 0);
  app->add_flag("--keep-boundary", o->keep_boundary, "Boundary vertices never move and are never removed");
  add_real_option(
      *app, "--feature-angle", o->feature_angle,
      "Edges whose faces meet at more than this dihedral angle (degrees) are kept like boundaries", 0);
  add_real_option(*app, "--feature-weight", o->feature_weight,
                  "Weight of the planes that keep feature edges (0: none)", 0);
  app->add_flag("--break-seams", o->break_seams,
                "Lift the seam rule of decimation (collapses off a UV seam stay refused)");
  add_real_option(*app, "--attribute-weight", o->attribute_weight,
                  "Weight of texture distortion in the error (0: none)", 0);
  add_real_option(
      *app, "--max-normal-change", o->max_normal_change,
      "Refuse collapses that turn a face by more than this many degrees (given: to the end; by default\n"
      "60, raised to 90 should it alone stop the run short of its target)",
      0, 180);
  add_ascii_flag(*app, o->ascii);
  app->callback([app, ratio, faces, vertices, o] {
    o->normal_change_given = app->get_option("--max-normal-change")->count() > 0;
    if (ratio->count() + faces->count() + vertices->count() + app->get_option("--max-error")->count() == 0)
      throw CLI::ValidationError("decimate", "give --ratio, --faces, --vertices or --max-error");
  });
}

}  // namespace

const CommandBinder decimate_command =
    bind_command<DecimateCommandOptions, add_decimate_arguments, run_decimate>;

}  // namespace hedge::cli
