// NativeMesh, the native half of the JS API's Mesh (hedge.js): construction and queries
// (wasm_mesh.cpp), edits and algorithms (wasm_edits.cpp) and fracture (wasm_fracture.cpp).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "hedge/algorithms/fracture.h"
#include "wasm_support.h"

namespace hedge::wasm {

//! A fracture material from the object the JS layer made of a custom material (arguments.js's
//! customMaterial(): {name, rings (Float64Array, 3 per ring), grain, grainStretch, refineEdge,
//! absolute}, typed); the fracture functions check the values (wasm_fracture.cpp).
FractureMaterial material_from_js(const val& m);

//! Filled by WasmMesh::pick and read by the JS layer as a Float64Array at pickScratchAddress():
//! [face, t, px, py, pz, halfedge, edge, vertex, edgeDistance, vertexDistance, c0, c1, c2, b0, b1, b2].
extern double g_pick[16];

class WasmMesh {
 public:
  WasmMesh() : s_(std::make_shared<MeshState>()) {}
  explicit WasmMesh(std::shared_ptr<MeshState> state) : s_(std::move(state)) {}
  std::shared_ptr<MeshState> state() const { return s_; }

  // ---- Construction and queries (wasm_mesh.cpp) ----

  //! positions: 3 floats per vertex; indices: the corners of the faces; face_sizes: corners per
  //! face, or empty/undefined for triangles.
  static WasmMesh from_buffers(val positions, val indices, val face_sizes, int policy, int weld);
  //! A file's bytes, read by hedge's reader for the format of `name`'s extension, then built with
  //! the file defaults (repair policy, exact welding for STL), as read_mesh() does.
  static WasmMesh from_file(const std::string& bytes, const std::string& name);
  WasmMesh clone() const;
  val build_report() const;
  val counts() const;
  val validate() const;
  bool is_triangle_mesh() const;
  //! A view of the position array (3 floats per vertex slot, deleted slots included); no copy.
  val positions_view() const;
  val position(std::uint32_t v) const;
  void set_position(std::uint32_t v, val p);
  //! The records of half-edge h, as the half-edge article draws them.
  val halfedge(std::uint32_t h) const;
  val vertex(std::uint32_t v) const;
  val edge(std::uint32_t e) const;
  //! f's half-edges in order: {face, halfedge, halfedges, vertices (their targets), edges, faces
  //! (across each edge, -1 on the boundary), boundary}.
  val face(std::uint32_t f) const;
  //! The one-ring of v, clockwise: outgoing half-edges, neighbours, edges, and the face of each
  //! outgoing half-edge (-1 across a boundary gap).
  val one_ring(std::uint32_t v) const;
  //! Casts a ray against the faces through the mesh's picking tree (binding::picking_tree). Returns
  //! the hit face or -1, and fills g_pick (see there).
  double pick(double ox, double oy, double oz, double dx, double dy, double dz);
  //! Casts n rays (6 floats each: origin, direction) and writes each hit face, or -1, into `out`
  //! (an Int32Array of n entries). Returns the number of hits.
  std::uint32_t pick_many(val rays, val out);
  //! The live mesh as index buffers (copies): {positions, indices, faceSizes (null for triangles)}.
  val to_arrays(bool triangulate) const;
  //! The mesh written in the format of name's extension, as write_mesh() writes a file (STL
  //! triangulated by fans; PLY and STL binary). A copy (Uint8Array).
  val to_file(const std::string& name) const;
  double memory_bytes() const;

  // ---- Edits and algorithms (wasm_edits.cpp) ----

  //! "" if the edit (binding::parse_edit: splitEdge, collapse, flip, splitFace, cutFace, fillHole)
  //! is allowed on the elements (a JS array of indices), else the library's refusal.
  std::string refusal(const std::string& edit, val elements) const;
  //! Splits e at `point` ([x, y, z]; undefined: the midpoint). Returns the new vertex.
  double split_edge(std::uint32_t e, val point);
  double flip(std::uint32_t e);
  //! Merges from_vertex(h) into to_vertex(h), which keeps its position unless `point` is given.
  //! Returns the surviving vertex.
  double collapse(std::uint32_t h, val point);
  //! Splits f at `point` (undefined: its centroid). Returns the new vertex.
  double split_face(std::uint32_t f, val point);
  //! Cuts the face of h0 and h1 from the target of h0 to the target of h1. Returns the new half-edge.
  double cut_face(std::uint32_t h0, std::uint32_t h1);
  //! Fills the hole whose boundary loop holds h. Returns the new faces.
  val fill_hole(std::uint32_t h);
  //! Removes deleted elements; every index may change.
  void garbage_collection();
  void subdivide(const std::string& scheme, int steps);
  void smooth(const std::string& method, int iterations, double lambda, double mu, bool fix_boundary);
  //! Decimates to target_faces faces (0: none) and target_vertices vertices (0: none), stopping
  //! before a collapse whose error exceeds max_error (negative: no limit).
  val decimate(double target_faces, double target_vertices, double max_error, bool relax_normal_change);
  //! Corner normals with hard edges where faces meet at more than crease_degrees (0..180) into
  //! "h:normal" (normals.h), which RenderBuffers with automatic normals draws and keeps up.
  void compute_corner_normals(double crease_degrees);

  // ---- Fracture (wasm_fracture.cpp) ----

  //! Breaks the mesh at `impact` (fracture.h), through the mesh's picking tree (binding::
  //! picking_tree: built if missing, kept up to date), so the cost is that of the broken area.
  //! `preset`: a preset's name, or "" for the material in `custom`: {name, rings (Float64Array, 3
  //! per ring: points, spacing, jitter), grain ([x, y, z]), grainStretch, refineEdge, units (a
  //! FractureUnits name), radius}, whose types the JS layer has checked. `units` (a name) and
  //! `radius` (!= 0) replace the material's; then `break_radius` != 0 puts the material in model
  //! units with that radius (fracture_material_at_radius; 0: as it is). `shell_thickness`: the thin
  //! shell open shards are weighed as (0: automatic). Returns {shards: {count, scalars
  //! (kShardScalars per shard: faces, area, volume, closed, mass, hull dimension, hull tolerance,
  //! centroid, centre of mass, principal moments, the three principal axes, inertia (9), shell
  //! thickness), meshes (NativeMesh each),
  //! hullPositions, hullIndices (each hull's indices count from its first vertex),
  //! hullVertexOffsets, hullIndexOffsets (count + 1 each)}, impactFace, impactPoint, breakRadius
  //! (model units), seconds:
  //! {locate, scatter, cut, detach, hulls, fracture (the whole call), pack (making this result)}}.
  //! fracture() checks everything before it edits, so a refusal leaves the mesh as it was. Running
  //! out of wasm memory halfway is not rolled back (a copy of the mesh would cost more than the
  //! strike, whose own allocations are those of the small broken area).
  val fracture(val impact, const std::string& preset, val custom, double seed, double break_radius,
               const std::string& units, double radius, double thickness, double density,
               double shell_thickness, double tolerance, bool hulls);

  // ---- Solid fracture (wasm_fracture_solid.cpp) ----

  //! Breaks the closed mesh at `impact` into closed pieces (fracture_solid.h), through the mesh's
  //! picking tree. `preset`/`custom` as for fracture(); `options`: {radius, radiusFraction, seed,
  //! innerSubmesh, density, tolerance, hulls}, numbers and a boolean the JS layer has typed.
  //! Returns {pieces: {count, scalars (kPieceScalars per piece: faces, volume, cap area, mass, hull
  //! dimension, hull tolerance, centroid, centre of mass, principal moments, the three principal
  //! axes, inertia (9)), meshes (NativeMesh each), hullPositions, hullIndices, hullVertexOffsets,
  //! hullIndexOffsets (as fracture()'s)}, bonds (Float64Array, 3 per bond: a, b (-1: the remaining
  //! object), area), impactFace, impactPoint, radius, seconds: {locate, cells, clip, cap, assemble,
  //! perPiece, fracture (the whole call), pack}}. A refused strike leaves the mesh as it was.
  val fracture_solid(val impact, const std::string& preset, val custom, val options);
  //! Why the mesh cannot be solid-fractured at `impact` with these options (as fracture_solid()):
  //! {code, message}, code the refusal's name (binding::name(SolidRefusal): "none", "open",
  //! "non_manifold", ...) and message "" when it can; checks the broken region only, through the
  //! picking tree.
  val solid_fracture_check(val impact, const std::string& preset, val custom, val options);

 private:
  std::shared_ptr<MeshState> s_;
};

}  // namespace hedge::wasm
