#include "hedge/core/surface_mesh.h"

#include <algorithm>
#include <cstring>
#include <type_traits>
#include <utility>

#include "hedge/error.h"

namespace hedge {

namespace {
constexpr const char* kPositionName = "v:position";
}

SurfaceMesh::SurfaceMesh() { positions_ = VertexProperty<Vec3>(vprops_.add<Vec3>(kPositionName, Vec3{})); }

SurfaceMesh::SurfaceMesh(const SurfaceMesh& o)
    : h_vertex_(o.h_vertex_),
      h_next_(o.h_next_),
      h_face_(o.h_face_),
      v_halfedge_(o.v_halfedge_),
      f_halfedge_(o.f_halfedge_),
      v_deleted_(o.v_deleted_),
      e_deleted_(o.e_deleted_),
      f_deleted_(o.f_deleted_),
      deleted_vertices_(o.deleted_vertices_),
      deleted_edges_(o.deleted_edges_),
      deleted_faces_(o.deleted_faces_),
      vprops_(o.vprops_),
      hprops_(o.hprops_),
      eprops_(o.eprops_),
      fprops_(o.fprops_),
      positions_(vprops_.get<Vec3>(kPositionName)) {}

SurfaceMesh& SurfaceMesh::operator=(const SurfaceMesh& o) {
  if (this != &o) {
    SurfaceMesh copy(o);
    *this = std::move(copy);  // the change log keeps this mesh's consumers and marks a reset
    changes_.notify();
  }
  return *this;
}

// Property arrays live behind unique_ptrs, so moving the containers keeps positions_ valid.
SurfaceMesh::SurfaceMesh(SurfaceMesh&& o) noexcept = default;
SurfaceMesh& SurfaceMesh::operator=(SurfaceMesh&& o) noexcept = default;

Halfedge SurfaceMesh::prev(Halfedge h) const {
  if (!is_boundary(h)) {
    Halfedge p = h;
    for (Halfedge n = next(p); n != h; n = next(n)) p = n;
    return p;
  }
  // About the origin: the incoming half-edge whose next is h.
  Halfedge g = twin(h);
  while (next(g) != h) g = twin(next(g));
  return g;
}

bool SurfaceMesh::is_boundary(Face f) const {
  for (Halfedge h : halfedges(f))
    if (is_boundary(twin(h))) return true;
  return false;
}

bool SurfaceMesh::is_manifold(Vertex v) const {
  std::size_t gaps = 0;
  for (Halfedge h : halfedges(v))
    if (is_boundary(h)) ++gaps;
  return gaps < 2;
}

std::size_t SurfaceMesh::valence(Vertex v) const { return halfedges(v).count(); }
std::size_t SurfaceMesh::valence(Face f) const { return halfedges(f).count(); }

bool SurfaceMesh::is_triangle_mesh() const {
  for (Face f : faces()) {
    Halfedge h = halfedge(f);
    if (next(next(next(h))) != h) return false;
  }
  return true;
}

bool SurfaceMesh::is_quad_mesh() const {
  for (Face f : faces()) {
    Halfedge h = halfedge(f);
    if (next(next(next(next(h)))) != h) return false;
  }
  return true;
}

Halfedge SurfaceMesh::find_halfedge(Vertex a, Vertex b) const {
  for (Halfedge h : halfedges(a))
    if (to_vertex(h) == b) return h;
  return Halfedge();
}

Edge SurfaceMesh::find_edge(Vertex a, Vertex b) const {
  Halfedge h = find_halfedge(a, b);
  return h.is_valid() ? edge(h) : Edge();
}

std::vector<Edge> SurfaceMesh::adjacent_edges(Edge e) const {
  std::vector<Edge> out;
  out.reserve(12);
  for (unsigned i = 0; i < 2; ++i)
    for (Edge a : edges(vertex(e, i)))
      if (a != e) out.push_back(a);
  return out;
}

std::vector<Halfedge> SurfaceMesh::boundary_loops() const {
  std::vector<Halfedge> loops;
  std::vector<bool> seen(halfedge_slots(), false);
  for (Halfedge h : halfedges()) {
    if (!is_boundary(h) || seen[h.idx()]) continue;
    loops.push_back(h);
    Halfedge g = h;
    // A damaged mesh could hold an open chain; the step limit keeps this finite.
    for (std::size_t steps = 0; steps <= halfedge_slots() && !seen[g.idx()]; ++steps) {
      seen[g.idx()] = true;
      g = next(g);
    }
  }
  return loops;
}

bool SurfaceMesh::remove_vertex_property(std::string_view name) {
  if (name == kPositionName) return false;
  return vprops_.remove(name);
}

void SurfaceMesh::grow_flags(std::vector<bool>& flags, std::size_t n) {
  flags.resize(std::max(n, 2 * flags.size()), false);
}

namespace {
// Gives v capacity `capacity` (if it has less), moving its elements with one memcpy.
template <typename T>
void grow_array(std::vector<T>& v, std::size_t capacity) {
  static_assert(std::is_trivially_copyable_v<T>, "moved with memcpy");
  if (v.capacity() >= capacity) return;
  std::vector<T> bigger;
  bigger.reserve(capacity);
  bigger.resize(v.size());  // a fill, cheaper than std::vector's element-by-element move
  if (!v.empty()) std::memcpy(bigger.data(), v.data(), v.size() * sizeof(T));
  v.swap(bigger);
}

std::size_t doubled(std::size_t capacity, std::size_t size, std::size_t n) {
  return std::max({2 * capacity, size + n, std::size_t(16)});
}
}  // namespace

void SurfaceMesh::grow_vertices(std::size_t n) {
  const std::size_t capacity = doubled(v_halfedge_.capacity(), v_halfedge_.size(), n);
  grow_array(v_halfedge_, capacity);
  grow_array(positions_.vector(), capacity);
}

void SurfaceMesh::grow_halfedges(std::size_t n) {
  const std::size_t capacity = doubled(h_vertex_.capacity(), h_vertex_.size(), n);
  grow_array(h_vertex_, capacity);
  grow_array(h_next_, capacity);
  grow_array(h_face_, capacity);
}

void SurfaceMesh::grow_faces(std::size_t n) {
  grow_array(f_halfedge_, doubled(f_halfedge_.capacity(), f_halfedge_.size(), n));
}

void SurfaceMesh::adjust_outgoing_halfedge(Vertex v) {
  for (Halfedge h : halfedges(v)) {
    if (is_boundary(h)) {
      set_halfedge(v, h);
      return;
    }
  }
}

void SurfaceMesh::mark_deleted(Vertex v) {
  if (!v_deleted_[v.idx()]) {
    v_deleted_[v.idx()] = true;
    ++deleted_vertices_;
  }
}
void SurfaceMesh::mark_deleted(Edge e) {
  if (!e_deleted_[e.idx()]) {
    e_deleted_[e.idx()] = true;
    ++deleted_edges_;
  }
}
void SurfaceMesh::mark_deleted(Face f) {
  if (!f_deleted_[f.idx()]) {
    f_deleted_[f.idx()] = true;
    ++deleted_faces_;
  }
}

void SurfaceMesh::reserve(std::size_t n_v, std::size_t n_e, std::size_t n_f) {
  v_halfedge_.reserve(n_v);
  v_deleted_.reserve(n_v);
  vprops_.reserve(n_v);
  h_vertex_.reserve(2 * n_e);
  h_next_.reserve(2 * n_e);
  h_face_.reserve(2 * n_e);
  e_deleted_.reserve(n_e);
  hprops_.reserve(2 * n_e);
  eprops_.reserve(n_e);
  f_halfedge_.reserve(n_f);
  f_deleted_.reserve(n_f);
  fprops_.reserve(n_f);
}

namespace {
// Resizes v to n; a growth gets exactly n elements, not a doubling. No huge-page advice here:
// with the kernel's default defrag policy ("madvise") an advised fault compacts memory on the spot,
// and after other large allocations were freed that stalled a 1.38M-triangle Catmull-Clark step
// from 0.94 s to 2.4 s (bench/peers --only catmull_clark_quads armadillo.obj:sub2, same run of
// peers); without the advice it takes the 0.94 s it took alone with it.
template <typename T>
void resize_for_rebuild(std::vector<T>& v, std::size_t n) {
  if (n > v.capacity()) v.reserve(n);
  v.resize(n);
}
}  // namespace

SurfaceMesh::Connectivity SurfaceMesh::release_connectivity(std::size_t n_v, std::size_t n_e,
                                                            std::size_t n_f) {
  Connectivity old;
  old.h_vertex.swap(h_vertex_);
  old.h_next.swap(h_next_);
  old.h_face.swap(h_face_);
  old.v_halfedge.swap(v_halfedge_);
  old.f_halfedge.swap(f_halfedge_);
  resize(n_v, n_e, n_f);
  return old;
}

void SurfaceMesh::swap_elements(SurfaceMesh& other) noexcept {
  h_vertex_.swap(other.h_vertex_);
  h_next_.swap(other.h_next_);
  h_face_.swap(other.h_face_);
  v_halfedge_.swap(other.v_halfedge_);
  f_halfedge_.swap(other.f_halfedge_);
  v_deleted_.swap(other.v_deleted_);
  e_deleted_.swap(other.e_deleted_);
  f_deleted_.swap(other.f_deleted_);
  std::swap(deleted_vertices_, other.deleted_vertices_);
  std::swap(deleted_edges_, other.deleted_edges_);
  std::swap(deleted_faces_, other.deleted_faces_);
  vprops_.swap_values(other.vprops_);
  hprops_.swap_values(other.hprops_);
  eprops_.swap_values(other.eprops_);
  fprops_.swap_values(other.fprops_);
  changes_.mark_reset();
}

void SurfaceMesh::resize(std::size_t n_v, std::size_t n_e, std::size_t n_f) {
  resize_for_rebuild(h_vertex_, 2 * n_e);
  resize_for_rebuild(h_next_, 2 * n_e);
  resize_for_rebuild(h_face_, 2 * n_e);
  resize_for_rebuild(v_halfedge_, n_v);
  resize_for_rebuild(f_halfedge_, n_f);
  v_deleted_.resize(n_v, false);
  vprops_.resize(n_v);
  e_deleted_.resize(n_e, false);
  hprops_.resize(2 * n_e);
  eprops_.resize(n_e);
  f_deleted_.resize(n_f, false);
  fprops_.resize(n_f);
  changes_.mark_reset();
  changes_.notify();
}

namespace {
// Old-to-new map keeping the first `size` elements that are not deleted, in order (the flags may
// be longer than the element arrays).
std::vector<Index> keep_map(const std::vector<bool>& deleted, std::size_t size, std::size_t& kept) {
  std::vector<Index> map(size, kInvalidIndex);
  Index n = 0;
  for (std::size_t i = 0; i < size; ++i)
    if (!deleted[i]) map[i] = n++;
  kept = n;
  return map;
}

template <typename H>
H remap(H h, const std::vector<Index>& map) {
  return h.is_valid() && h.idx() < map.size() ? H(map[h.idx()]) : H();
}

template <typename T>
void compact_vector(std::vector<T>& v, const std::vector<Index>& map, std::size_t n) {
  std::vector<T> out(n);
  for (std::size_t i = 0; i < v.size(); ++i)
    if (map[i] != kInvalidIndex) out[map[i]] = v[i];
  v.swap(out);
}
}  // namespace

GarbageMaps SurfaceMesh::garbage_collection() {
  GarbageMaps maps;
  std::size_t nv = 0, ne = 0, nf = 0;
  maps.vertices = keep_map(v_deleted_, vertex_slots(), nv);
  maps.edges = keep_map(e_deleted_, edge_slots(), ne);
  maps.faces = keep_map(f_deleted_, face_slots(), nf);
  maps.halfedges.assign(halfedge_slots(), kInvalidIndex);
  for (std::size_t e = 0; e < maps.edges.size(); ++e) {
    if (maps.edges[e] == kInvalidIndex) continue;
    maps.halfedges[2 * e] = 2 * maps.edges[e];
    maps.halfedges[2 * e + 1] = 2 * maps.edges[e] + 1;
  }
  if (!has_garbage()) return maps;
  apply_maps(maps, nv, ne, nf);
  return maps;
}

void SurfaceMesh::apply_maps(const GarbageMaps& maps, std::size_t nv, std::size_t ne, std::size_t nf) {
  for (auto& v : h_vertex_) v = remap(v, maps.vertices);
  for (auto& h : h_next_) h = remap(h, maps.halfedges);
  for (auto& f : h_face_) f = remap(f, maps.faces);
  for (auto& h : v_halfedge_) h = remap(h, maps.halfedges);
  for (auto& h : f_halfedge_) h = remap(h, maps.halfedges);

  compact_vector(h_vertex_, maps.halfedges, 2 * ne);
  compact_vector(h_next_, maps.halfedges, 2 * ne);
  compact_vector(h_face_, maps.halfedges, 2 * ne);
  compact_vector(v_halfedge_, maps.vertices, nv);
  compact_vector(f_halfedge_, maps.faces, nf);
  vprops_.compact(maps.vertices, nv);
  hprops_.compact(maps.halfedges, 2 * ne);
  eprops_.compact(maps.edges, ne);
  fprops_.compact(maps.faces, nf);
  v_deleted_.assign(nv, false);
  e_deleted_.assign(ne, false);
  f_deleted_.assign(nf, false);
  deleted_vertices_ = deleted_edges_ = deleted_faces_ = 0;
  // Every index may have moved: consumers of the change log rebuild.
  changes_.mark_reset();
  changes_.notify();
}

GarbageMaps SurfaceMesh::renumber(std::vector<Index> new_vertex, std::vector<Index> new_edge,
                                  std::vector<Index> new_face) {
  // Each map must send the live elements onto 0..n-1, one to one, and the deleted ones nowhere.
  auto check = [](const std::vector<Index>& map, const std::vector<bool>& deleted, std::size_t slots,
                  std::size_t live, const char* what) {
    if (map.size() != slots)
      throw InvalidInputError(std::string("renumber: the ") + what + " map has " +
                              std::to_string(map.size()) + " entries for " + std::to_string(slots) +
                              " slots");
    std::vector<bool> taken(live, false);
    for (std::size_t i = 0; i < slots; ++i) {
      if (deleted[i]) {
        if (map[i] != kInvalidIndex)
          throw InvalidInputError(std::string("renumber: deleted ") + what + " " + std::to_string(i) +
                                  " is given a new index");
        continue;
      }
      if (map[i] >= live || taken[map[i]])
        throw InvalidInputError(std::string("renumber: the ") + what +
                                " map is not a one-to-one numbering of the " + std::to_string(live) +
                                " live elements (at " + std::to_string(i) + ")");
      taken[map[i]] = true;
    }
  };
  check(new_vertex, v_deleted_, vertex_slots(), n_vertices(), "vertex");
  check(new_edge, e_deleted_, edge_slots(), n_edges(), "edge");
  check(new_face, f_deleted_, face_slots(), n_faces(), "face");
  GarbageMaps maps;
  maps.vertices = std::move(new_vertex);
  maps.edges = std::move(new_edge);
  maps.faces = std::move(new_face);
  maps.halfedges.assign(halfedge_slots(), kInvalidIndex);
  for (std::size_t e = 0; e < maps.edges.size(); ++e) {
    if (maps.edges[e] == kInvalidIndex) continue;
    maps.halfedges[2 * e] = 2 * maps.edges[e];
    maps.halfedges[2 * e + 1] = 2 * maps.edges[e] + 1;
  }
  apply_maps(maps, n_vertices(), n_edges(), n_faces());
  return maps;
}

void SurfaceMesh::shrink_to_fit() {
  h_vertex_.shrink_to_fit();
  h_next_.shrink_to_fit();
  h_face_.shrink_to_fit();
  v_halfedge_.shrink_to_fit();
  f_halfedge_.shrink_to_fit();
  v_deleted_.resize(vertex_slots());  // the flags may have grown ahead of the elements
  e_deleted_.resize(edge_slots());
  f_deleted_.resize(face_slots());
  v_deleted_.shrink_to_fit();
  e_deleted_.shrink_to_fit();
  f_deleted_.shrink_to_fit();
  vprops_.shrink_to_fit();
  hprops_.shrink_to_fit();
  eprops_.shrink_to_fit();
  fprops_.shrink_to_fit();
}

std::size_t SurfaceMesh::memory_bytes() const {
  auto bits = [](const std::vector<bool>& b) { return (b.capacity() + 7) / 8; };
  return h_vertex_.capacity() * sizeof(Vertex) + h_next_.capacity() * sizeof(Halfedge) +
         h_face_.capacity() * sizeof(Face) + v_halfedge_.capacity() * sizeof(Halfedge) +
         f_halfedge_.capacity() * sizeof(Halfedge) + bits(v_deleted_) + bits(e_deleted_) + bits(f_deleted_) +
         vprops_.bytes() + hprops_.bytes() + eprops_.bytes() + fprops_.bytes();
}

}  // namespace hedge
