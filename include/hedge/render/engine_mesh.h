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

namespace hedge {

//! An engine's mesh arrays (a Unity Mesh, a glTF primitive): n vertices, triangle indices.
//! Optional streams are empty or hold one entry per vertex.
struct EngineMeshView {
  std::span<const Vec3> positions;
  std::span<const std::uint32_t> indices;  //!< 3 per triangle
  std::span<const Vec3> normals;
  std::span<const Vec2> texcoords;
  std::span<const Color> colors;
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
//! texcoords and colours per corner ("h:normal", "h:texcoord", "h:color"), so that a RenderBuffers
//! with the same winding and axes reproduces the engine's triangles and attributes exactly. It
//! records the engine vertex of every corner and vertex (kCornerSource, kVertexSource).
//! \throw InvalidInputError on mismatched stream sizes, indices out of range or non-finite values;
//!        TopologyError under the strict policy.
SurfaceMesh from_engine_mesh(const EngineMeshView& view, const EngineImportOptions& options = {},
                             BuildReport* report = nullptr);

}  // namespace hedge
