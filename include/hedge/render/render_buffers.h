// RenderBuffers: engine-ready vertex and index buffers kept in step with a SurfaceMesh.
//
//  - Render vertices. A mesh vertex becomes one render vertex per distinct set of corner
//    attributes around it: corners whose "h:texcoord", "h:normal", "h:color", "h:tangent" or
//    "h:texcoord1" differ (a UV seam, a hard edge) get separate render vertices, as engines need.
//  - Stable slots. Each face owns fixed triangles in the index buffer ((n - 2) for an n-gon) and
//    each render vertex a fixed slot in the vertex buffer. Freed slots go to free lists and are
//    reused; until then a freed triangle is degenerate (three equal indices) and a freed vertex
//    keeps stale data that no triangle references. compact() removes the holes.
//  - Incremental updates. Operations mark what they touch in the mesh's change log
//    (core/changes.h); sync() rewrites only the slots of touched faces and vertices and returns the
//    rewritten ranges, sorted and merged, for a partial GPU upload.
//  - Submeshes (materials). A face's submesh is its "f:submesh" face property (std::int32_t), 0
//    without it. The index buffer holds one region per submesh, in increasing order, so that each
//    submesh is one contiguous index range (submesh()). Every region but the last has spare room,
//    free triangle slots kept degenerate, so that edits stay local; a region that overflows (or a
//    face of a submesh beyond the last one) makes the sync a full rebuild, which lays the regions out
//    again with new room. A mesh without "f:submesh" has one region: the whole buffer.
//  - Transactions. begin() ... edits ... commit() syncs once at the end. A transaction belongs to
//    the RenderBuffers that opened it; the mesh's change log counts it for this RenderBuffers' consumer
//    (ChangeLog::begin(id)). So another RenderBuffers of the same mesh, or code that calls
//    mesh.changes().begin() itself, does not defer this one's syncs, while every open transaction
//    defers the notifications of the log's subscribers until it closes.
//
// The RenderBuffers refers to the mesh it was made for: the mesh must outlive it and stay at the same
// address.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "hedge/core/build.h"
#include "hedge/core/color.h"
#include "hedge/core/export.h"
#include "hedge/core/surface_mesh.h"
#include "hedge/render/tangent.h"

namespace hedge {

//! Where the normal stream comes from. With `automatic`, the default, normals follow the geometry;
//! `attribute` keeps imported normals as they are, whatever moves.
enum class NormalSource {
  none,  //!< no normal stream
  //! "h:normal" corners, else "v:normal" vertices, as they are: never recomputed, so a moved vertex
  //! keeps its imported normal. None if neither exists. (A RenderBuffers of the same mesh with
  //! `automatic` normals rewrites that property, and this one then shows what it wrote.)
  attribute,
  computed,  //!< area-weighted smooth vertex normals, recomputed around every edit
  //! The mesh's normals ("h:normal", else "v:normal") if it has some, following the geometry: at
  //! each sync, the normals of every vertex of a face an edit touched (a moved vertex, a new or
  //! changed face) are recomputed, area-weighted, and written into that property. Corners of such a
  //! vertex that held one normal share the new one; corners that held different normals (a hard
  //! edge) are recomputed from their own faces, so creases stay. Untouched vertices keep their
  //! imported normals. Computed normals if the mesh has none. Cost: proportional to the edit.
  automatic,
};

struct RenderOptions {
  NormalSource normals = NormalSource::automatic;
  //! Texcoords from "h:texcoord" corners, else "v:texcoord" vertices, when present.
  bool texcoords = true;
  //! Colours from "h:color" corners, else "v:color" vertices (type Color), when present.
  bool colors = true;
  //! Tangents from "h:tangent" corners (Vec4: xyz, handedness w), when present. They are kept as
  //! imported, not computed (no MikkTSpace): where normals follow the geometry (NormalSource::
  //! automatic with imported normals), each corner whose normal a sync recomputes gets its tangent
  //! made perpendicular to the new normal again (Gram-Schmidt, orthogonal_tangent()), w kept; new
  //! corners of edits get interpolated tangents. With flip_x, x and w are negated.
  bool tangents = true;
  //! A second texcoord channel (lightmaps) from "h:texcoord1" corners, when present.
  bool texcoords1 = true;
  //! One buffer of whole vertices (position, normal, texcoord, colour) or one buffer per stream.
  bool interleaved = true;
  //! Triangle winding in the index buffer, and whether to negate x of positions and normals: for
  //! writing into a convention other than the mesh's own (mirrored data). Unity needs neither: its
  //! clockwise front faces in left-handed axes have the same cross-product normals as hedge's
  //! counter-clockwise faces in right-handed axes, so its meshes are taken and given back as they are.
  Winding winding = Winding::ccw;
  bool flip_x = false;
};

//! Where each attribute sits in a vertex, in floats. An absent attribute has offset -1.
//! Interleaved: all in vertices(), `stride` floats per vertex, in the order position, normal,
//! texcoord, color, tangent, texcoord1. Separate: each in its own stream, tightly packed (3, 3, 2, 4,
//! 4 and 2 floats).
struct VertexLayout {
  std::uint32_t stride = 3;
  std::int32_t position = 0;
  std::int32_t normal = -1;
  std::int32_t texcoord = -1;
  std::int32_t color = -1;
  std::int32_t tangent = -1;
  std::int32_t texcoord1 = -1;
  bool interleaved = true;
};

//! A run of slots: elements [first, first + count).
struct SlotRange {
  std::uint32_t first = 0;
  std::uint32_t count = 0;
  friend bool operator==(const SlotRange&, const SlotRange&) = default;
};

//! What one sync() rewrote.
struct SyncResult {
  //! Rewritten render vertices, sorted, merged, disjoint. In separate-stream layout the same ranges
  //! apply to every stream.
  std::vector<SlotRange> vertex_ranges;
  //! Rewritten index-buffer entries (indices, not triangles), sorted, merged, disjoint.
  std::vector<SlotRange> index_ranges;
  std::size_t vertex_bytes = 0;  //!< bytes in vertex_ranges, all streams
  std::size_t index_bytes = 0;   //!< bytes in index_ranges
  std::size_t faces_synced = 0;
  std::size_t vertices_synced = 0;  //!< render vertices written
  //! The buffers grew (or were rebuilt): reallocate the GPU buffers, then upload everything.
  bool resized = false;
  bool full = false;  //!< everything was rebuilt (first sync, reset, garbage collection)
  bool empty() const { return vertex_ranges.empty() && index_ranges.empty(); }
};

//! One submesh's part of the buffers: what Unity's SubMeshDescriptor (and a draw call) needs.
struct SubmeshRange {
  std::uint32_t index_start = 0;  //!< first entry of the index buffer
  //! Index-buffer entries, spare and free triangles (degenerate) included.
  std::uint32_t index_count = 0;
  //! The render vertices its index entries refer to (free slots' entries, which are 0, included) lie
  //! in [first_vertex, first_vertex + vertex_count); both 0 for an empty range.
  std::uint32_t first_vertex = 0;
  std::uint32_t vertex_count = 0;
  //! The box of the positions its live triangles use, as written in the vertex buffer (x negated
  //! with flip_x); both (0, 0, 0) without live triangles.
  Vec3 min{0, 0, 0};
  Vec3 max{0, 0, 0};
};

//! Old-to-new slot maps from compact(); freed slots map to kInvalidIndex.
struct RenderRemap {
  std::vector<Index> vertices;   //!< render vertex slot -> new slot
  std::vector<Index> triangles;  //!< triangle slot -> new triangle slot
};

class RenderBuffers {
 public:
  //! Builds the buffers (a full export) and starts following `mesh`'s change log.
  explicit RenderBuffers(SurfaceMesh& mesh, const RenderOptions& options = {});
  //! Stops following the mesh's change log and closes the transactions this RenderBuffers left open
  //! (closing the last open one notifies the log's subscribers).
  ~RenderBuffers();
  RenderBuffers(const RenderBuffers&) = delete;
  RenderBuffers& operator=(const RenderBuffers&) = delete;

  const RenderOptions& options() const { return options_; }
  const VertexLayout& layout() const { return layout_; }
  SurfaceMesh& mesh() const { return *mesh_; }

  // ---- Buffers. *_slots count storage slots, free ones included; n_* count the slots in use. ----
  //! Render vertex slots: the length of the vertex buffer in vertices.
  std::size_t vertex_slots() const { return rv_vertex_.size(); }
  //! Triangle slots: the length of the index buffer in triangles.
  std::size_t triangle_slots() const { return indices_.size() / 3; }
  //! The length of the index buffer in indices (3 per triangle slot).
  std::size_t index_count() const { return indices_.size(); }
  //! Render vertices and triangles in use.
  std::size_t n_vertices() const { return vertex_slots() - free_vertices_.size(); }
  std::size_t n_triangles() const { return triangle_slots() - free_triangle_slots_; }
  //! Sizes to allocate the GPU buffers at (render vertices, indices). The buffers grow within them
  //! without a reallocation; SyncResult::resized says when they grew beyond.
  std::size_t vertex_capacity() const { return vertex_capacity_; }
  std::size_t index_capacity() const { return index_capacity_; }
  //! Free triangle slots (degenerate triangles) waiting for reuse or compact(), the spare room of
  //! every submesh region but the last included.
  std::size_t free_triangle_slots() const { return free_triangle_slots_; }
  //! Interleaved layout: every vertex, layout().stride floats each. Separate: the positions.
  std::span<const float> vertices() const { return streams_[0]; }
  //! One stream in separate layout (empty if the attribute is absent or the layout interleaved).
  std::span<const float> positions() const {
    return layout_.interleaved ? std::span<const float>() : streams_[0];
  }
  std::span<const float> normals() const { return stream(1); }
  std::span<const float> texcoords() const { return stream(2); }
  std::span<const float> colors() const { return stream(3); }
  std::span<const float> tangents() const { return stream(4); }
  std::span<const float> texcoords1() const { return stream(5); }
  std::span<const std::uint32_t> indices() const { return indices_; }
  //! Render vertex -> mesh vertex (invalid for a free slot): the vertex map.
  std::span<const Vertex> render_vertex_source() const { return rv_vertex_; }
  //! The render vertex of the corner entered by half-edge h (invalid for boundary half-edges).
  //! Valid after a sync that saw the corner's face.
  Index render_vertex(Halfedge h) const {
    if (!h.is_valid() || h.idx() >= corner_rv_.size() || mesh_->is_deleted(h) || mesh_->is_boundary(h))
      return kInvalidIndex;
    return corner_rv_[h.idx()];
  }
  //! First triangle slot of face f and its triangle count (count 0 if f has none).
  SlotRange triangles(Face f) const;
  //! The face that owns triangle slot t, the inverse of triangles(Face): what an engine's ray hit
  //! (Unity's RaycastHit.triangleIndex, which counts triangles of the uploaded index buffer) names.
  //! Invalid for a free slot or t >= triangle_slots(). As of the last sync, like the buffers: the
  //! face may have been deleted by an edit since. O(1).
  Face triangle_face(std::size_t t) const {
    return t < triangle_face_.size() ? Face(triangle_face_[t]) : Face();
  }
  //! Triangle slot -> face index (kInvalidIndex for a free slot), triangle_slots() entries.
  std::span<const Index> triangle_faces() const { return triangle_face_; }
  //! Submeshes: 1 + the largest "f:submesh" of a face at the last full build (at least 1). A face's
  //! submesh is at most 65535: the constructor, rebuild() and a sync that must rebuild throw
  //! InvalidInputError for a larger one (a sync leaves the buffers as its last good state, and the
  //! edits stay pending until the id is fixed). A negative one counts as 0.
  std::size_t submesh_count() const { return regions_.size(); }
  //! Submesh i's index range, vertex range and bounds, as of the last sync. O(1), except the first
  //! call after a full build (the first sync, rebuild(), a region's overflow) or compact(), which
  //! measures every submesh exactly: O(buffer). Each sync then grows the ranges and boxes by what it
  //! rewrote (O(what changed)), so after vertices move inward a box may be larger than its submesh,
  //! never smaller: a conservative box for culling.
  //! \throw InvalidInputError if i >= submesh_count().
  SubmeshRange submesh(std::size_t i) const;
  //! The submesh whose region holds face f's triangles (0 for a face without any).
  std::uint32_t face_submesh(Face f) const {
    return f.is_valid() && f.idx() < face_region_.size() ? face_region_[f.idx()] : 0;
  }
  //! Render vertices beyond one per used mesh vertex: what seams cost.
  std::size_t seam_splits() const;
  //! Bytes of the whole vertex and index buffers (a full upload).
  std::size_t buffer_bytes() const;

  // ---- Updates. ----
  //! Brings the buffers in step with every change marked since the last sync. Cost proportional
  //! to what changed. Inside a transaction it does nothing and returns an empty result.
  const SyncResult& sync();
  //! The result of the last sync (or commit, or rebuild).
  const SyncResult& last_result() const { return result_; }
  //! Opens a transaction: changes are gathered, and notifications wait (transactions nest).
  void begin();
  //! Closes the transaction opened by begin(); the outermost commit syncs once. Without an open
  //! transaction of this RenderBuffers it does nothing and returns an empty result.
  const SyncResult& commit();
  //! True between begin() and the matching outermost commit(). O(consumers of the mesh).
  bool in_transaction() const { return mesh_->changes().in_transaction(changes_.id()); }
  //! Rebuilds every buffer from scratch, a full export. Slots restart in
  //! face order, so it also compacts.
  const SyncResult& rebuild();
  //! Syncs, then removes free slots by packing live render vertices and face triangles in their
  //! current order, submesh by submesh (each region but the last keeps spare room, as a full build
  //! leaves it); returns the old-to-new maps. O(buffer). Every slot may have moved, so
  //! last_result() and the result of the next sync() (or commit()) report whole buffers, `full`
  //! and `resized`: a consumer that only follows sync results (an engine component) uploads
  //! everything after a compaction it did not make itself.
  RenderRemap compact();

 private:
  std::span<const float> stream(int i) const;
  bool stream_present(int s) const;
  //! Floats per vertex held in streams_[s]: the whole vertex in stream 0 when interleaved, 0 for a
  //! stream not stored.
  std::uint32_t stored_width(int s) const;
  void resize_streams(std::size_t n);
  //! Grows `capacity` geometrically to hold n; a growth outside a full build is reported as resized.
  void grow_capacity(std::size_t& capacity, std::size_t n);
  void report_full();
  //! sync() without the full report a compaction leaves pending.
  void sync_changes();
  void attach_sources();
  void setup_layout();
  void grow_element_arrays();
  void full_build();
  void sync_face(Face f);
  void release_face(Face f);
  void fill_vertex(Vertex v, Halfedge h, float* out) const;
  void read_vertex(Index rv, float* out) const;
  void store_vertex(Index rv, const float* data);
  //! Rewrites the vertex-sourced floats of v's render vertices, recording those that changed.
  void rewrite_vertex_data(Vertex v);
  Index find_or_add_render_vertex(Halfedge corner);
  Index allocate_vertex();
  void unref_vertex(Index rv);
  //! Triangle slots for `count` triangles in region r (the submesh's region).
  std::uint32_t allocate_triangles(std::uint32_t count, std::uint32_t r);
  void free_triangles(std::uint32_t first, std::uint32_t count, std::uint32_t r);
  //! The region face f's triangles belong in: its "f:submesh" (negative counts as 0).
  std::uint32_t wanted_region(Face f) const;
  //! \throw InvalidInputError if a face's submesh is above 65535 (each id costs a region).
  void check_submeshes() const;
  //! Lays out one region per submesh for a full build, each but the last with spare room.
  void layout_regions();
  //! compact(): packs the triangles of live faces region by region, keeping the spare room.
  void pack_triangles(RenderRemap& map);
  void mark_indices_written(std::uint32_t first, std::uint32_t count);
  void finish_result();
  //! Fills normal_seeds_ with the vertices whose normals the pending changes affect.
  void seed_normals(const ChangeLog::Pending& p);
  void update_normal(Vertex w);
  //! Recomputes w's normals into the mesh's normal property (automatic normals with an attribute).
  void follow_normal(Vertex w);

  SurfaceMesh* mesh_;
  RenderOptions options_;
  VertexLayout layout_;
  //! This object's place in the mesh's change log (detached when it is destroyed).
  ChangeConsumer changes_;
  bool building_ = false;      // a full build reports whole buffers, not written slots
  bool full_pending_ = false;  // compact() moved every slot: the next sync reports whole buffers

  // Attribute sources, resolved against the mesh's properties.
  HalfedgeProperty<Vec3> h_normal_;
  VertexProperty<Vec3> v_normal_;
  HalfedgeProperty<Vec2> h_texcoord_;
  VertexProperty<Vec2> v_texcoord_;
  HalfedgeProperty<Color> h_color_;
  VertexProperty<Color> v_color_;
  HalfedgeProperty<Vec4> h_tangent_;
  HalfedgeProperty<Vec2> h_texcoord1_;
  bool computed_normals_ = false;
  bool follow_normals_ = false;      // attribute normals, recomputed into the mesh around edits
  std::vector<Vec3> vertex_normal_;  // computed normals, per mesh vertex
  std::vector<std::uint32_t> normal_stamp_;
  std::uint32_t normal_generation_ = 0;
  std::vector<Vertex> normal_seeds_;
  std::vector<Face> normal_faces_;
  std::vector<std::pair<Vec3, Vec3d>> normal_groups_;  // follow_normal: old value, new sum
  std::vector<std::size_t> normal_corner_group_;       // follow_normal: group of each corner

  // Vertex buffer: streams_[0] interleaved (or positions), [1..5] normals, texcoords, colours,
  // tangents, second texcoords.
  static constexpr int kStreams = 6;
  std::vector<float> streams_[kStreams];
  std::vector<Vertex> rv_vertex_;       // slot -> mesh vertex
  std::vector<Index> rv_next_;          // next render vertex of the same mesh vertex
  std::vector<std::uint32_t> rv_refs_;  // index-buffer entries using the slot
  std::vector<Index> free_vertices_;
  std::vector<Index> v_first_rv_;  // mesh vertex -> first render vertex
  std::vector<Index> corner_rv_;   // half-edge -> render vertex of the corner it enters
  std::size_t vertex_capacity_ = 0;

  // Index buffer.
  std::vector<std::uint32_t> indices_;
  std::vector<SlotRange> face_slots_;  // face -> its triangle slots
  std::vector<Index> triangle_face_;   // triangle slot -> its face (the inverse of face_slots_)
  // Free triangle slots by region, then by triangle count: first slots.
  std::vector<std::vector<std::vector<std::uint32_t>>> free_triangles_;
  std::size_t free_triangle_slots_ = 0;
  std::size_t index_capacity_ = 0;

  // Submesh regions of the index buffer, in triangle slots; the last one grows at the buffer's end.
  struct Region {
    std::uint32_t first = 0;
    std::uint32_t capacity = 0;  // slots it spans (the last: those it used so far)
    std::uint32_t used = 0;      // slots [first, first + used) handed out at least once
    // What submesh() reports: measured by the first submesh() after a full build or compact(),
    // then grown by each sync (mutable: measuring is a cache of what the buffers hold).
    mutable std::uint32_t vertex_lo = 0, vertex_hi = 0;  // index entries' range, [lo, hi]
    mutable bool has_vertices = false;
    mutable Vec3 box_lo{0, 0, 0}, box_hi{0, 0, 0};  // live triangles' positions
    mutable bool has_box = false;
  };
  //! The region that holds triangle slot t.
  std::uint32_t region_of_slot(std::uint32_t t) const;
  //! Grows region r's vertex range (and, for a live triangle's entry, its box) by render vertex rv.
  void include_in_region(const Region& g, std::uint32_t rv, bool live) const;
  //! Recomputes every region's vertex range and box from the buffers. O(buffer).
  void measure_regions() const;
  //! Grows the regions by what this sync wrote. O(what changed).
  void grow_regions();
  FaceProperty<std::int32_t> f_submesh_;
  std::vector<Region> regions_{Region{}};
  std::vector<std::uint32_t> face_region_;  // face -> region of its triangle slots
  bool region_overflow_ = false;            // a region ran out of room: this sync rebuilds
  // The regions' ranges and boxes are measured (by the first submesh() since a full build or
  // compact()): until then syncs need not grow them, so buffers nobody asks pay nothing.
  mutable bool regions_measured_ = false;

  // Scratch of sync_face, kept to avoid allocating per face.
  std::vector<Halfedge> corners_;
  std::vector<Index> corner_rvs_;
  std::vector<std::array<Index, 3>> tris_;
  std::vector<Vec3d> points_;
  std::vector<std::uint32_t> new_indices_;
  std::vector<Face> dirty_faces_;

  // Written slots of the current sync.
  std::vector<std::uint32_t> written_vertices_;
  std::vector<SlotRange> written_indices_;
  SyncResult result_;
};

// Deprecated names (kept for one release): the previous release's name of RenderBuffers.
using RenderSync [[deprecated("use RenderBuffers")]] = RenderBuffers;
// End of deprecated names

}  // namespace hedge
