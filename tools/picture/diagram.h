// The half-edge diagram: a small mesh drawn as in a textbook, with every half-edge as an arrow
// inside its face (so the two half-edges of an edge, its twins, run side by side in opposite
// directions), boundary half-edges as red arrows outside the mesh, and labels v<i>, f<i>, h<i>.
#pragma once

#include <cstddef>

#include "camera.h"
#include "canvas.h"
#include "hedge/core/surface_mesh.h"

namespace hedge::picture {

struct DiagramOptions {
  //! Most faces a diagram draws; a larger mesh is refused (the labels would not fit).
  std::size_t max_faces = 400;
  bool labels = true;
  //! A legend line at the bottom.
  bool legend = true;
};

//! A camera for the diagram of mesh: looking straight at it, orthographic, when it is flat (its
//! bounding box is thin along one axis), else perspective from the iso view.
Camera diagram_camera(const SurfaceMesh& mesh, double aspect);

//! Draws the diagram onto canvas, faces back to front and translucent (those facing away fainter),
//! then the boundary half-edges and the vertices.
//! \throw InvalidInputError for a mesh with no faces or more than options.max_faces, a position
//!   that is not finite, or a canvas too small for the legend.
void draw_halfedge_diagram(const SurfaceMesh& mesh, const Camera& camera, Canvas& canvas,
                           const DiagramOptions& options = {});

}  // namespace hedge::picture
