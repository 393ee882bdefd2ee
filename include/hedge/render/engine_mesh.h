// Engine meshes: one attribute set per vertex, seams as duplicated vertices. from_engine_mesh()
// turns such arrays into a SurfaceMesh whose attributes live on the corners, the inverse of what
// RenderBuffers (render/render_buffers.h) writes.
#pragma once

#include <cstdint>
#include <span>

#include "hedge/core/build.h"
#include "hedge/core/color.h"
#include "hedge/core/export.h"
#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"
#include "hedge/render/tangent.h"

namespace hedge {

//! An engine's mesh arrays (a Unity Mesh, a glTF primitive): n vertices, triangle indices.
//! Optional streams are empty or hold one entry per vertex.
struct EngineMeshView {
  std::span<const Vec3> positions;
  std::span<const std::uint32_t> indices;  //!< 3 per triangle
  std::span<const Vec3> normals;
  std::span<const Vec2> texcoords;
  std::span<const Color> colors;
  //! Empty, or one submesh (material) per triangle, each in [0, 65535]: written into the face
  //! property "f:submesh" (std::int32_t), which RenderBuffers groups the index buffer by. An engine
  //! mesh of several submeshes passes its triangles submesh after submesh with their ids.
  std::span<const std::int32_t> submeshes;
  //! Optional, one per vertex: tangents (xyz and the handedness w, Unity's Mesh.tangents), kept per
  //! corner as "h:tangent", and a second texcoord channel (lightmaps, Unity's uv2), kept per corner
  //! as "h:texcoord1". Edits interpolate both like any corner property.
  std::span<const Vec4> tangents;
  std::span<const Vec2> texcoords1;
};

struct EngineImportOptions {
  //! How positions are welded into one topological vertex; attributes stay per corner, so seams
  //! survive any welding.
  Weld weld = Weld::exact;
  double weld_epsilon = 1e-6;
  TopologyPolicy policy = TopologyPolicy::repair;
  //! Conversions for data in another convention: reverse the triangles' winding, negate x of
  //! positions and normals. A Unity mesh needs neither (see RenderOptions::winding): importing it
  //! with the defaults keeps the user's coordinates bit for bit and gives Unity's normals.
  Winding winding = Winding::ccw;
  bool flip_x = false;
};

//! The map back to the engine's vertex indices that from_engine_mesh() records (std::int32_t):
//! per corner, the engine vertex it came from; per vertex, the first (smallest) engine vertex
//! welded into it (seams weld several). -1 for boundary half-edges and for the vertices and
//! corners later edits make; the values follow their elements through edits and garbage
//! collection, so data keyed by the engine's vertex index is found again.
inline constexpr const char* kCornerSource = "h:source";
inline constexpr const char* kVertexSource = "v:source";

//! Builds a SurfaceMesh from engine arrays, welding positions for topology and keeping normals,
//! texcoords, colours, tangents and second texcoords per corner ("h:normal", "h:texcoord",
//! "h:color", "h:tangent", "h:texcoord1") and submeshes per face ("f:submesh"), each only when given,
//! so that a RenderBuffers with the same winding and axes reproduces the engine's triangles and
//! attributes exactly. flip_x negates x of tangents and their handedness w too. It records the
//! engine vertex of every corner and vertex (kCornerSource, kVertexSource).
//! \throw InvalidInputError on mismatched stream sizes, indices out of range, non-finite values or
//!        submesh ids outside [0, 65535];
//!        TopologyError under the strict policy.
SurfaceMesh from_engine_mesh(const EngineMeshView& view, const EngineImportOptions& options = {},
                             BuildReport* report = nullptr);

}  // namespace hedge
