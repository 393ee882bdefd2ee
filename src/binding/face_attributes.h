// A face added with its attributes, as every binding does it: per-corner texture coordinates (the
// corner property "h:texcoord", Vec2) and the face's submesh, the material slot an engine draws it
// with (the face property "f:submesh", std::int32_t, default 0). Everything is checked before the
// mesh changes: a bad attribute fails (HEDGE_ERROR_INVALID_ARGUMENT), a refused face is refused
// (HEDGE_ERROR_REFUSED, see edits.h), and either way the mesh is left exactly as it was.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "hedge/core/surface_mesh.h"

namespace hedge::binding {

//! What a new face carries besides its corners.
struct FaceAttributes {
  //! One per corner, in the corners' order, written into "h:texcoord" (added, (0, 0) at every other
  //! corner, when the mesh has none); empty: the corners get the property's default, if it exists.
  std::span<const Vec2> texcoords;
  //! Written into "f:submesh" (added, 0 for every other face, when the mesh has none); none: the
  //! face gets the property's default, 0.
  std::optional<std::int32_t> submesh;
};

//! Adds a face with these live corners (binding::live_vertices()) and attributes. \return the face.
//! \throw BindingError HEDGE_ERROR_INVALID_ARGUMENT, saying which attribute and why: texcoords
//! whose count is not the corners', a coordinate that is not finite, a submesh outside
//! [0, kMaxSubmesh], a mesh that keeps texcoords per vertex ("v:texcoord") or whose "h:texcoord" or
//! "f:submesh" has another type; HEDGE_ERROR_REFUSED if add_face_refusal() refuses.
Face add_face(SurfaceMesh& m, std::span<const Vertex> corners, const FaceAttributes& attributes);

}  // namespace hedge::binding
