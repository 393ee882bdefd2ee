// SurfaceMesh: a polygon half-edge mesh with real boundary half-edges.
//
// Storage (see docs/design.md):
//  - half-edges come in pairs: twin(h) = h ^ 1, edge(h) = h >> 1; no twin or edge array exists;
//  - each half-edge stores the vertex it points to, the next half-edge in its face (or boundary
//    loop) and its face (invalid on a boundary half-edge); prev is derived, not stored;
//  - each vertex stores one outgoing half-edge, a boundary one when the vertex is on a boundary;
//  - each face stores one half-edge; the face's corners start at that half-edge's target vertex;
//  - deletion is a bit per element; garbage_collection() compacts.
// Positions are the float x3 vertex property "v:position".
//
// Threads: a SurfaceMesh has no lock of its own. Any number of threads may read one mesh at once
// (every const member, the ranges and circulators, the const free functions of the library), as
// long as none edits it. An edit (any non-const member or function taking a non-const mesh:
// operations, properties, garbage_collection(), the algorithms that change the mesh) needs the
// mesh to itself: no other thread may read or edit it meanwhile. The change log lent to const
// readers is the one exception to "const is a read": attaching, detaching and consuming through
// watch_changes() count as edits (core/changes.h). Different meshes are independent. Functions
// that start worker threads of their own say so in their header (core/threads.h lists them).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "hedge/core/changes.h"
#include "hedge/core/handles.h"
#include "hedge/core/properties.h"
#include "hedge/core/ranges.h"
#include "hedge/core/vec.h"

// Forces the element appends into the local operations that call them (they are a few stores
// each, and the operations call them once per element).
#if defined(__GNUC__) || defined(__clang__)
#define HEDGE_ALWAYS_INLINE [[gnu::always_inline]]
#else
#define HEDGE_ALWAYS_INLINE
#endif

namespace hedge {

//! Old-to-new index maps returned by garbage_collection(); removed elements map to kInvalidIndex.
struct GarbageMaps {
  std::vector<Index> vertices;
  std::vector<Index> halfedges;
  std::vector<Index> edges;
  std::vector<Index> faces;
};

class SurfaceMesh;

class SurfaceMesh {
 public:
  SurfaceMesh();
  SurfaceMesh(const SurfaceMesh& other);
  SurfaceMesh& operator=(const SurfaceMesh& other);
  SurfaceMesh(SurfaceMesh&& other) noexcept;
  SurfaceMesh& operator=(SurfaceMesh&& other) noexcept;
  ~SurfaceMesh() = default;

  // ---- Counts. n_* count live elements; *_slots count storage slots, deleted ones included, so
  // element indices run from 0 to the slot count - 1 until garbage_collection(). ----
  std::size_t n_vertices() const { return vertex_slots() - deleted_vertices_; }
  std::size_t n_edges() const { return edge_slots() - deleted_edges_; }
  std::size_t n_halfedges() const { return 2 * n_edges(); }
  std::size_t n_faces() const { return face_slots() - deleted_faces_; }
  std::size_t vertex_slots() const { return v_halfedge_.size(); }
  std::size_t halfedge_slots() const { return h_vertex_.size(); }
  std::size_t edge_slots() const { return h_vertex_.size() / 2; }
  std::size_t face_slots() const { return f_halfedge_.size(); }
  bool is_empty() const { return n_vertices() == 0; }
  bool has_garbage() const { return deleted_vertices_ + deleted_edges_ + deleted_faces_ > 0; }

  // ---- Connectivity, O(1) unless noted. ----
  static Halfedge twin(Halfedge h) { return Halfedge(h.idx() ^ 1u); }
  static Edge edge(Halfedge h) { return Edge(h.idx() >> 1); }
  //! Half-edge i (0 or 1) of e; halfedge(e, 0) points from vertex(e, 0) to vertex(e, 1).
  static Halfedge halfedge(Edge e, unsigned i) { return Halfedge((e.idx() << 1) | (i & 1u)); }

  Vertex to_vertex(Halfedge h) const { return h_vertex_[h.idx()]; }
  Vertex from_vertex(Halfedge h) const { return h_vertex_[h.idx() ^ 1u]; }
  Halfedge next(Halfedge h) const { return h_next_[h.idx()]; }
  //! The half-edge before h in its face or boundary loop. prev is not stored: this walks the
  //! face of an interior half-edge (O(face degree); two steps on a triangle) and rotates about the
  //! origin of a boundary half-edge (O(valence)).
  Halfedge prev(Halfedge h) const;
  Face face(Halfedge h) const { return h_face_[h.idx()]; }
  Halfedge halfedge(Vertex v) const { return v_halfedge_[v.idx()]; }
  Halfedge halfedge(Face f) const { return f_halfedge_[f.idx()]; }
  Vertex vertex(Edge e, unsigned i) const { return to_vertex(halfedge(e, i ^ 1u)); }
  //! Face i (0 or 1) of e; invalid on the boundary side.
  Face face(Edge e, unsigned i) const { return face(halfedge(e, i)); }
  //! Clockwise neighbour of outgoing half-edge h about its origin: O(1).
  Halfedge rotate_cw(Halfedge h) const { return next(twin(h)); }
  //! Counter-clockwise neighbour of outgoing half-edge h about its origin: costs one prev().
  Halfedge rotate_ccw(Halfedge h) const { return twin(prev(h)); }

  bool is_boundary(Halfedge h) const { return !face(h).is_valid(); }
  bool is_boundary(Edge e) const { return is_boundary(halfedge(e, 0)) || is_boundary(halfedge(e, 1)); }
  //! True if v lies on a boundary or is isolated. O(1): a boundary vertex's half-edge is a boundary one.
  bool is_boundary(Vertex v) const {
    Halfedge h = halfedge(v);
    return !h.is_valid() || is_boundary(h);
  }
  //! True if any edge of f is on the boundary. O(face degree).
  bool is_boundary(Face f) const;
  bool is_isolated(Vertex v) const { return !halfedge(v).is_valid(); }
  //! True if the faces about v form one fan (at most one boundary gap). O(valence).
  //! Meshes built by hedge are always manifold; this is for checking edited or foreign meshes.
  bool is_manifold(Vertex v) const;
  //! Number of edges at v. O(valence).
  std::size_t valence(Vertex v) const;
  //! Number of corners of f. O(face degree).
  std::size_t valence(Face f) const;
  //! True if every live face is a triangle. O(#faces).
  bool is_triangle_mesh() const;
  //! True if every live face is a quad. O(#faces).
  bool is_quad_mesh() const;
  //! The half-edge from a to b, or an invalid handle. O(valence of a).
  Halfedge find_halfedge(Vertex a, Vertex b) const;
  //! The edge between a and b, or an invalid handle. O(valence of a).
  Edge find_edge(Vertex a, Vertex b) const;

  // ---- Deletion state. ----
  bool is_deleted(Vertex v) const { return v_deleted_[v.idx()]; }
  bool is_deleted(Edge e) const { return e_deleted_[e.idx()]; }
  bool is_deleted(Halfedge h) const { return e_deleted_[h.idx() >> 1]; }
  bool is_deleted(Face f) const { return f_deleted_[f.idx()]; }
  //! True if the handle indexes a slot of this mesh (deleted or not); false for an invalid handle.
  bool is_valid(Vertex v) const { return v.idx() < vertex_slots(); }
  bool is_valid(Halfedge h) const { return h.idx() < halfedge_slots(); }
  bool is_valid(Edge e) const { return e.idx() < edge_slots(); }
  bool is_valid(Face f) const { return f.idx() < face_slots(); }
  //! True if the handle names a live element of this mesh: valid, in range and not deleted. O(1).
  bool is_live(Vertex v) const { return is_valid(v) && !is_deleted(v); }
  bool is_live(Halfedge h) const { return is_valid(h) && !is_deleted(h); }
  bool is_live(Edge e) const { return is_valid(e) && !is_deleted(e); }
  bool is_live(Face f) const { return is_valid(f) && !is_deleted(f); }

  // ---- Positions. ----
  Vec3& position(Vertex v) { return positions_[v]; }
  const Vec3& position(Vertex v) const { return positions_[v]; }
  VertexProperty<Vec3> positions() const { return positions_; }
  //! Moves v and marks it in the change log (position() gives a reference that marks nothing).
  void set_position(Vertex v, const Vec3& p) {
    positions_[v] = p;
    changes_.mark(v, ChangeEvent::vertices_moved);
    changes_.notify();
  }

  // ---- Change tracking (see core/changes.h). Operations mark what they touch; code that writes
  // positions through position() or properties directly marks with mark_changed(). ----
  ChangeLog& changes() { return changes_; }
  const ChangeLog& changes() const { return changes_; }
  //! The consumer side of the change log, for readers that hold a const mesh (FaceBvh): watching a
  //! mesh does not change it. See ChangeWatch.
  ChangeWatch watch_changes() const { return ChangeWatch(changes_); }
  //! v's position or another of its properties changed.
  void mark_changed(Vertex v, ChangeEvent events = ChangeEvent::vertices_moved) { changes_.mark(v, events); }
  //! f's corners, corner properties or face properties changed.
  void mark_changed(Face f, ChangeEvent events = ChangeEvent::faces_changed) { changes_.mark(f, events); }

  // ---- Properties. Names starting with "v:", "h:", "e:", "f:" are by convention hedge's own. ----
  template <typename T>
  VertexProperty<T> add_vertex_property(std::string_view name, T def = T()) {
    return VertexProperty<T>(vprops_.add<T>(name, std::move(def)));
  }
  template <typename T>
  HalfedgeProperty<T> add_halfedge_property(std::string_view name, T def = T()) {
    return HalfedgeProperty<T>(hprops_.add<T>(name, std::move(def)));
  }
  template <typename T>
  EdgeProperty<T> add_edge_property(std::string_view name, T def = T()) {
    return EdgeProperty<T>(eprops_.add<T>(name, std::move(def)));
  }
  template <typename T>
  FaceProperty<T> add_face_property(std::string_view name, T def = T()) {
    return FaceProperty<T>(fprops_.add<T>(name, std::move(def)));
  }
  //! The property of that name and type; an empty (false) Property if there is none.
  template <typename T>
  VertexProperty<T> get_vertex_property(std::string_view name) const {
    return VertexProperty<T>(vprops_.get<T>(name));
  }
  template <typename T>
  HalfedgeProperty<T> get_halfedge_property(std::string_view name) const {
    return HalfedgeProperty<T>(hprops_.get<T>(name));
  }
  template <typename T>
  EdgeProperty<T> get_edge_property(std::string_view name) const {
    return EdgeProperty<T>(eprops_.get<T>(name));
  }
  template <typename T>
  FaceProperty<T> get_face_property(std::string_view name) const {
    return FaceProperty<T>(fprops_.get<T>(name));
  }
  //! Get the property, adding it if it does not exist.
  template <typename T>
  VertexProperty<T> vertex_property(std::string_view name, T def = T()) {
    auto p = get_vertex_property<T>(name);
    return p ? p : add_vertex_property<T>(name, std::move(def));
  }
  template <typename T>
  HalfedgeProperty<T> halfedge_property(std::string_view name, T def = T()) {
    auto p = get_halfedge_property<T>(name);
    return p ? p : add_halfedge_property<T>(name, std::move(def));
  }
  template <typename T>
  EdgeProperty<T> edge_property(std::string_view name, T def = T()) {
    auto p = get_edge_property<T>(name);
    return p ? p : add_edge_property<T>(name, std::move(def));
  }
  template <typename T>
  FaceProperty<T> face_property(std::string_view name, T def = T()) {
    auto p = get_face_property<T>(name);
    return p ? p : add_face_property<T>(name, std::move(def));
  }
  //! Removes a property; "v:position" cannot be removed. Returns false if nothing was removed.
  bool remove_vertex_property(std::string_view name);
  bool remove_halfedge_property(std::string_view name) { return hprops_.remove(name); }
  bool remove_edge_property(std::string_view name) { return eprops_.remove(name); }
  bool remove_face_property(std::string_view name) { return fprops_.remove(name); }
  std::vector<std::string> vertex_property_names() const { return vprops_.names(); }
  std::vector<std::string> halfedge_property_names() const { return hprops_.names(); }
  std::vector<std::string> edge_property_names() const { return eprops_.names(); }
  std::vector<std::string> face_property_names() const { return fprops_.names(); }

  // ---- Element ranges (skip deleted elements). ----
  ElementRange<Vertex> vertices() const { return {v_deleted_, vertex_slots()}; }
  ElementRange<Halfedge> halfedges() const { return {e_deleted_, halfedge_slots(), 1}; }
  ElementRange<Edge> edges() const { return {e_deleted_, edge_slots()}; }
  ElementRange<Face> faces() const { return {f_deleted_, face_slots()}; }

  // ---- Circulators (cheap ranges for range-for). The default vertex order is clockwise, which
  // costs O(1) a step; the *_ccw variants cost one prev() a step. ----
  //! Outgoing half-edges of v, clockwise.
  VertexCirculator<SurfaceMesh, HalfedgeOf> halfedges(Vertex v) const { return {this, halfedge(v)}; }
  VertexCirculator<SurfaceMesh, HalfedgeOf, true> halfedges_ccw(Vertex v) const {
    return {this, halfedge(v)};
  }
  //! Neighbouring vertices of v, clockwise.
  VertexCirculator<SurfaceMesh, TargetOf> vertices(Vertex v) const { return {this, halfedge(v)}; }
  VertexCirculator<SurfaceMesh, TargetOf, true> vertices_ccw(Vertex v) const { return {this, halfedge(v)}; }
  //! Incident faces of v, clockwise (boundary gaps skipped).
  VertexCirculator<SurfaceMesh, FaceOf> faces(Vertex v) const { return {this, halfedge(v)}; }
  VertexCirculator<SurfaceMesh, FaceOf, true> faces_ccw(Vertex v) const { return {this, halfedge(v)}; }
  //! Incident edges of v, clockwise.
  VertexCirculator<SurfaceMesh, EdgeOf> edges(Vertex v) const { return {this, halfedge(v)}; }
  //! Half-edges of f in order (counter-clockwise for a CCW-oriented face).
  LoopCirculator<SurfaceMesh, HalfedgeOf> halfedges(Face f) const { return {this, halfedge(f)}; }
  //! Corners of f in order, starting at the target of halfedge(f).
  LoopCirculator<SurfaceMesh, TargetOf> vertices(Face f) const { return {this, halfedge(f)}; }
  //! Edges of f in order.
  LoopCirculator<SurfaceMesh, EdgeOf> edges(Face f) const { return {this, halfedge(f)}; }
  //! Faces across the edges of f (the boundary side skipped).
  LoopCirculator<SurfaceMesh, TwinFaceOf> faces(Face f) const { return {this, halfedge(f)}; }
  //! The half-edges of the face or boundary loop that h belongs to, starting at h.
  LoopCirculator<SurfaceMesh, HalfedgeOf> loop(Halfedge h) const { return {this, h}; }
  //! The two vertices of e.
  std::array<Vertex, 2> vertices(Edge e) const { return {vertex(e, 0), vertex(e, 1)}; }
  //! The faces on either side of e: one or two (a boundary side is left out).
  FixedList<Face, 2> faces(Edge e) const {
    FixedList<Face, 2> out;
    if (Face f = face(e, 0); f.is_valid()) out.push_back(f);
    if (Face f = face(e, 1); f.is_valid()) out.push_back(f);
    return out;
  }
  //! Edges sharing a vertex with e, e itself excluded. O(valence of both ends).
  std::vector<Edge> adjacent_edges(Edge e) const;
  //! One boundary half-edge per boundary loop. O(#half-edges).
  std::vector<Halfedge> boundary_loops() const;

  // ---- Low-level construction and editing. These keep no invariant by themselves: they are the
  // building blocks of builders and local operations, which restore validity before returning. ----
  HEDGE_ALWAYS_INLINE Vertex add_vertex(const Vec3& p);
  //! Appends an edge (two half-edges) from a to b, all links unset. Returns halfedge(e, 0).
  HEDGE_ALWAYS_INLINE Halfedge new_edge(Vertex a, Vertex b);
  HEDGE_ALWAYS_INLINE Face new_face();
  //! Appends N edges, every link unset (their vertices too), and returns halfedge(first, 0); the
  //! others follow. Like N new_edge() calls, but each array grows once, by a block.
  template <std::size_t N>
  HEDGE_ALWAYS_INLINE Halfedge new_edges();
  //! Appends N faces, half-edges unset, and returns the first.
  template <std::size_t N>
  HEDGE_ALWAYS_INLINE Face new_faces();
  void set_vertex(Halfedge h, Vertex v) { h_vertex_[h.idx()] = v; }
  void set_next(Halfedge h, Halfedge n) { h_next_[h.idx()] = n; }
  void set_face(Halfedge h, Face f) { h_face_[h.idx()] = f; }
  void set_halfedge(Vertex v, Halfedge h) { v_halfedge_[v.idx()] = h; }
  void set_halfedge(Face f, Halfedge h) { f_halfedge_[f.idx()] = h; }
  //! Makes v's half-edge a boundary one if v has an outgoing boundary half-edge. O(valence).
  void adjust_outgoing_halfedge(Vertex v);
  //! Mark elements deleted; their storage stays until garbage_collection().
  void mark_deleted(Vertex v);
  void mark_deleted(Edge e);
  void mark_deleted(Face f);
  //! Property containers, for operations that carry every property of an element along.
  PropertyContainer& vertex_properties() { return vprops_; }
  PropertyContainer& halfedge_properties() { return hprops_; }
  PropertyContainer& edge_properties() { return eprops_; }
  PropertyContainer& face_properties() { return fprops_; }
  const PropertyContainer& vertex_properties() const { return vprops_; }
  const PropertyContainer& halfedge_properties() const { return hprops_; }
  const PropertyContainer& edge_properties() const { return eprops_; }
  const PropertyContainer& face_properties() const { return fprops_; }
  //! Reserve storage for n_v vertices, n_e edges and n_f faces.
  void reserve(std::size_t n_v, std::size_t n_e, std::size_t n_f);
  //! Resizes every element array (connectivity set to invalid). Used by builders.
  void resize(std::size_t n_v, std::size_t n_e, std::size_t n_f);
  //! The connectivity arrays, as release_connectivity() hands them over.
  struct Connectivity {
    std::vector<Vertex> h_vertex;
    std::vector<Halfedge> h_next;
    std::vector<Face> h_face;
    std::vector<Halfedge> v_halfedge, f_halfedge;
  };
  //! resize(n_v, n_e, n_f) for an algorithm that rewrites every link (subdivision): the old
  //! connectivity arrays are moved out and returned, not copied, and every link of the resized mesh
  //! is invalid, the old elements' too. Properties and deletion flags resize as in resize(). O(size).
  Connectivity release_connectivity(std::size_t n_v, std::size_t n_e, std::size_t n_f);
  //! Takes every element of `other` (connectivity, deletion flags, property values) and gives it
  //! this mesh's: for an algorithm that builds its result in a mesh of its own and then commits it
  //! without a step that could fail. The property arrays of this mesh stay the same objects (its
  //! handles stay valid) and take the values of the arrays of the same name and type in `other`,
  //! which should hold all of them (see PropertyContainer::add_missing_from). This mesh keeps its
  //! change log, which records a reset. O(arrays^2), never throws.
  void swap_elements(SurfaceMesh& other) noexcept;
  //! Removes deleted elements and compacts every array and property. Returns old-to-new maps so
  //! that handles held elsewhere (engine buffers) can be remapped. O(#elements).
  GarbageMaps garbage_collection();
  //! Renumbers the elements: new_vertex[v] is live vertex v's new index, likewise for edges (the
  //! half-edges of edge e follow it: 2e + i goes to 2 new_edge[e] + i) and faces. Each map must
  //! number the live elements 0..n-1 one to one and give deleted ones kInvalidIndex; garbage is
  //! collected at the same time. Properties move with their elements, and the change log records a
  //! reset. Returns the maps, as garbage_collection() does. O(#elements).
  //! \throw InvalidInputError, with the mesh unchanged, if a map is not such a numbering.
  GarbageMaps renumber(std::vector<Index> new_vertex, std::vector<Index> new_edge,
                       std::vector<Index> new_face);
  //! Releases spare capacity of every array.
  void shrink_to_fit();
  //! Heap bytes held by connectivity, flags and all properties (capacity, not size).
  std::size_t memory_bytes() const;

  // ---- Checking. ----
  //! Every broken invariant, one line each; empty means valid. O(#elements). See docs/design.md.
  //! Besides the connectivity, every live vertex's position must be finite: a NaN or infinite
  //! coordinate is reported as "vertex V has a non-finite position (x, y, z)". At most 1000 lines,
  //! then a count of the rest.
  std::vector<std::string> validate() const;

  // Raw arrays for tight loops and bindings (read-only).
  const std::vector<Vertex>& halfedge_vertex_array() const { return h_vertex_; }
  const std::vector<Halfedge>& halfedge_next_array() const { return h_next_; }
  const std::vector<Face>& halfedge_face_array() const { return h_face_; }
  const std::vector<Halfedge>& vertex_halfedge_array() const { return v_halfedge_; }
  const std::vector<Halfedge>& face_halfedge_array() const { return f_halfedge_; }

 private:
  friend class MeshBuilder;
  //! Moves every element to its index in maps (kInvalidIndex: dropped), leaving nv, ne and nf.
  void apply_maps(const GarbageMaps& maps, std::size_t nv, std::size_t ne, std::size_t nf);

  std::vector<Vertex> h_vertex_;
  std::vector<Halfedge> h_next_;
  std::vector<Face> h_face_;
  std::vector<Halfedge> v_halfedge_;
  std::vector<Halfedge> f_halfedge_;
  // The deletion flags may run ahead of their element arrays (the flags past the last element are
  // false): they grow geometrically, in cover(), rather than by one bit per new element.
  std::vector<bool> v_deleted_, e_deleted_, f_deleted_;
  static void cover(std::vector<bool>& flags, std::size_t n) {
    if (flags.size() < n) [[unlikely]]
      grow_flags(flags, n);
  }
  static void grow_flags(std::vector<bool>& flags, std::size_t n);
  // Growth of the connectivity arrays, in one place per element kind: when a kind runs out of
  // room, its arrays double together, each moved with one memcpy (handles and positions are
  // trivially copyable) rather than element by element as std::vector does.
  void room_for_vertices(std::size_t n) {
    if (v_halfedge_.capacity() - v_halfedge_.size() < n) [[unlikely]]
      grow_vertices(n);
  }
  void room_for_halfedges(std::size_t n) {
    if (h_vertex_.capacity() - h_vertex_.size() < n) [[unlikely]]
      grow_halfedges(n);
  }
  void room_for_faces(std::size_t n) {
    if (f_halfedge_.capacity() - f_halfedge_.size() < n) [[unlikely]]
      grow_faces(n);
  }
  void grow_vertices(std::size_t n);
  void grow_halfedges(std::size_t n);
  void grow_faces(std::size_t n);
  std::size_t deleted_vertices_ = 0, deleted_edges_ = 0, deleted_faces_ = 0;

  PropertyContainer vprops_, hprops_, eprops_, fprops_;
  VertexProperty<Vec3> positions_;
  // mutable for watch_changes(): consumers attach to, read and consume the log of a const mesh.
  mutable ChangeLog changes_;
};

// The element appends: room for the kind first (room_for_*: one check, and one doubling of all its
// arrays when full), then a push_back or a block insert per array; the deletion flags are covered
// in bulk, and a property container that holds no array costs one comparison.
inline Vertex SurfaceMesh::add_vertex(const Vec3& point) {
  const Vec3 p = point;  // point may live in the position array that is about to grow
  const Vertex v(static_cast<Index>(vertex_slots()));
  room_for_vertices(1);
  v_halfedge_.push_back(Halfedge());
  cover(v_deleted_, v_halfedge_.size());
  positions_.vector().push_back(p);
  vprops_.push_back_except(positions_.array());
  return v;
}

inline Halfedge SurfaceMesh::new_edge(Vertex a, Vertex b) {
  const Halfedge h(static_cast<Index>(halfedge_slots()));
  room_for_halfedges(2);
  h_vertex_.push_back(b);
  h_vertex_.push_back(a);
  h_next_.push_back(Halfedge());
  h_next_.push_back(Halfedge());
  h_face_.push_back(Face());
  h_face_.push_back(Face());
  cover(e_deleted_, edge_slots());
  hprops_.push_back(2);
  eprops_.push_back();
  return h;
}

inline Face SurfaceMesh::new_face() {
  const Face f(static_cast<Index>(face_slots()));
  room_for_faces(1);
  f_halfedge_.push_back(Halfedge());
  cover(f_deleted_, f_halfedge_.size());
  fprops_.push_back();
  return f;
}

// The block appends copy from constant arrays of invalid handles: a short fixed-size copy, where
// push_back would check the capacity and store the end once per element.
template <std::size_t N>
inline Halfedge SurfaceMesh::new_edges() {
  static constexpr std::array<Vertex, 2 * N> no_vertex{};
  static constexpr std::array<Halfedge, 2 * N> no_halfedge{};
  static constexpr std::array<Face, 2 * N> no_face{};
  const Halfedge h(static_cast<Index>(halfedge_slots()));
  room_for_halfedges(2 * N);
  h_vertex_.insert(h_vertex_.end(), no_vertex.begin(), no_vertex.end());
  h_next_.insert(h_next_.end(), no_halfedge.begin(), no_halfedge.end());
  h_face_.insert(h_face_.end(), no_face.begin(), no_face.end());
  cover(e_deleted_, edge_slots());
  hprops_.push_back(2 * N);
  eprops_.push_back(N);
  return h;
}

template <std::size_t N>
inline Face SurfaceMesh::new_faces() {
  static constexpr std::array<Halfedge, N> no_halfedge{};
  const Face f(static_cast<Index>(face_slots()));
  room_for_faces(N);
  f_halfedge_.insert(f_halfedge_.end(), no_halfedge.begin(), no_halfedge.end());
  cover(f_deleted_, f_halfedge_.size());
  fprops_.push_back(N);
  return f;
}

//! Throws InvalidInputError "WHAT: vertex V has a non-finite position (x, y, z)" for the first live
//! vertex whose position holds a NaN or an infinity. Whole-mesh algorithms that read positions call
//! it before they change anything, so a bad position is named rather than spread. O(#vertices).
void require_finite_positions(const SurfaceMesh& mesh, const char* what);

}  // namespace hedge

#undef HEDGE_ALWAYS_INLINE
