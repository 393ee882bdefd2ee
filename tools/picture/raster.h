// A small z-buffer renderer for pictures of a mesh, on the CPU: no GPU and no display needed.
//
// Faces are drawn as the fan triangles of their first corner (as to_indexed does), shaded with a
// head light, with their edges drawn inside each triangle at a distance computed per sample, so a
// hidden edge never shows through a face in front of it. Every pixel averages supersample^2
// samples, which anti-aliases silhouettes and lines. The picture is split into bands of rows, one
// per thread; the result does not depend on the number of threads.
#pragma once

#include <vector>

#include "camera.h"
#include "hedge/core/surface_mesh.h"
#include "image.h"

namespace hedge::picture {

enum class Shading {
  flat,    //!< one normal per face
  smooth,  //!< area-weighted vertex normals, interpolated
  unlit,   //!< the base colours as they are, for diagrams and tests
};

enum class ColorBy {
  none,       //!< one colour, RenderOptions::base
  face,       //!< a colour per face
  shard,      //!< a colour per connected component (the shards of a fracture); cap faces of a solid
              //!< fracture (face property "f:inner" = 1) in RenderOptions::inner_color
  curvature,  //!< mean curvature (cotangent Laplacian), blue (concave) to red (convex)
  valence,  //!< vertex valence: white where regular (6 among triangles, 4 among quads), blue below, red above
};

struct RenderOptions {
  int width = 800;
  int height = 600;
  //! Samples per pixel along each axis (1..4): 2 gives 4 samples per pixel.
  int supersample = 2;
  Shading shading = Shading::smooth;
  ColorBy color_by = ColorBy::none;
  //! Draw every edge.
  bool wireframe = false;
  //! Boundary edges in their own colour (also without the wireframe).
  bool boundary = true;
  //! Edges whose faces meet at more than this angle (degrees) are feature edges, drawn in their
  //! own colour; 0 draws none.
  double feature_angle = 0;
  //! Vertices drawn as dots in the `marked` colour: repaired or non-manifold ones, say.
  std::vector<Vertex> marked;
  Rgb background{255, 255, 255};
  Rgb base{186, 196, 214};
  Rgb wire{40, 44, 52};
  Rgb boundary_color{220, 40, 40};
  Rgb feature_color{235, 150, 20};
  Rgb marked_color{200, 0, 200};
  //! The cut faces of a solid fracture, with ColorBy::shard.
  Rgb inner_color{150, 70, 55};
  //! Width of a line in pixels.
  double line_width = 1.0;
  //! Most threads for the bands of rows (at most 16); 0: max_threads() (core/threads.h). Never
  //! more than max_threads().
  unsigned threads = 0;
};

//! A picture of the live faces of mesh seen through camera.
//! \throw InvalidInputError for a size check_size refuses, a supersample outside 1..4, more than
//!   kMaxPixels samples in all (about 470 MB of buffers), a mesh with
//!   no faces, a live vertex whose position is not finite, or a camera Projection refuses.
//! Cost: O(V + F) plus O(samples covered) per face, in O(width * height * supersample^2) memory.
Image render(const SurfaceMesh& mesh, const Camera& camera, const RenderOptions& options);

}  // namespace hedge::picture
