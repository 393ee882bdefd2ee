// The shaded picture of one mesh with the hedge tool's options: `hedge render` and the Python
// binding's hedge.render() both draw through shaded_picture(), so one set of options gives one
// picture in either.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "camera.h"
#include "hedge/core/surface_mesh.h"
#include "image.h"
#include "raster.h"

namespace hedge::picture {

struct ShadedOptions {
  int width = 800;
  int height = 600;
  //! The named view that frames the whole mesh; ignored when `camera` is given.
  View view = View::iso;
  //! An explicit camera (eye, target, up, field of view) instead of the framing view.
  std::optional<Camera> camera;
  Shading shading = Shading::smooth;
  ColorBy color_by = ColorBy::none;
  //! Draw every edge.
  bool wireframe = false;
  //! Edges whose faces meet at more than this angle (degrees) are drawn as features; 0: none.
  double feature_angle = 60;
  //! Samples per pixel along each axis, 1..4.
  int supersample = 2;
  //! Most threads for the bands of rows; 0: every core (at most 16).
  unsigned threads = 0;
  //! Vertices drawn as dots (the tool marks the vertices its repair split).
  std::vector<Vertex> marked;
};

//! The shading named `name` ("flat" or "smooth"). \throw InvalidInputError naming the valid ones.
Shading shading_named(std::string_view name);
//! The colouring named `name` ("none", "face", "shard", "curvature", "valence").
//! \throw InvalidInputError naming the valid ones.
ColorBy color_by_named(std::string_view name);
//! The view named `name` (parse_view). \throw InvalidInputError naming the valid ones.
View view_named(std::string_view name);

//! The memory the picture takes while it is drawn, in bytes: a depth key (float) and a colour per
//! sample, and the picture itself. Per-face arrays, in proportion to the mesh, come on top.
double shaded_picture_bytes(int width, int height, int supersample);

//! The shaded picture of the live faces of `mesh` with `options`: seen through options.camera, or
//! from options.view framing the whole mesh at the picture's aspect ratio.
//! \throw InvalidInputError as frame() and render() do: a bad size or supersample, a mesh with no
//!   faces, a position that is not finite, a camera that cannot project.
Image shaded_picture(const SurfaceMesh& mesh, const ShadedOptions& options);

}  // namespace hedge::picture
