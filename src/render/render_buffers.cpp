// RenderBuffers: see include/hedge/render/render_buffers.h.
//
// A render vertex is keyed by its mesh vertex and the values of the corner attributes it carries;
// the render vertices of one mesh vertex form a short singly linked list (usually one entry, two or
// three on a seam). Reference counts count index-buffer entries, so that a render vertex no
// triangle uses any more returns to the free list whatever the triangulation of its faces.
#include "hedge/render/render_buffers.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "hedge/core/triangulate.h"

namespace hedge {

namespace {
constexpr std::uint32_t kStreamWidth[6] = {3, 3, 2, 4, 4, 2};
constexpr std::size_t kMaxFloats = 18;
using Floats = std::array<float, kMaxFloats>;

// Capacity a buffer of n elements grows to: geometric, so that growth (a GPU reallocation) is rare.
std::size_t grown_capacity(std::size_t n, std::size_t old) {
  return std::max<std::size_t>({n, old + old / 2, 64});
}

// Twice the area times the unit normal (Newell), exact for planar polygons.
Vec3d face_normal_sum(const SurfaceMesh& m, Face f) {
  Vec3d n{0, 0, 0};
  for (Halfedge h : m.halfedges(f))
    add_newell_term(n, to_double(m.position(m.from_vertex(h))), to_double(m.position(m.to_vertex(h))));
  return n;
}

void merge_ranges(std::vector<SlotRange>& r) {
  std::sort(r.begin(), r.end(), [](const SlotRange& a, const SlotRange& b) { return a.first < b.first; });
  std::size_t out = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (out > 0 && r[i].first <= r[out - 1].first + r[out - 1].count) {
      const std::uint32_t end = std::max(r[out - 1].first + r[out - 1].count, r[i].first + r[i].count);
      r[out - 1].count = end - r[out - 1].first;
    } else {
      r[out++] = r[i];
    }
  }
  r.resize(out);
}
}  // namespace

RenderBuffers::RenderBuffers(SurfaceMesh& mesh, const RenderOptions& options)
    : mesh_(&mesh), options_(options), changes_(mesh.watch_changes()) {
  rebuild();  // if it throws, changes_ detaches as it is destroyed
}

RenderBuffers::~RenderBuffers() = default;

std::span<const float> RenderBuffers::stream(int i) const {
  if (layout_.interleaved) return {};
  return streams_[i];
}

SlotRange RenderBuffers::triangles(Face f) const {
  if (!f.is_valid() || f.idx() >= face_slots_.size()) return {};
  return face_slots_[f.idx()];
}

std::size_t RenderBuffers::seam_splits() const {
  std::size_t used = 0;
  for (Index first : v_first_rv_) used += first != kInvalidIndex;
  return n_vertices() - used;
}

std::size_t RenderBuffers::buffer_bytes() const {
  return vertex_slots() * layout_.stride * sizeof(float) + index_count() * sizeof(std::uint32_t);
}

// ---- Layout and sources -------------------------------------------------------------------------
void RenderBuffers::attach_sources() {
  const SurfaceMesh& m = *mesh_;
  h_normal_ = {};
  v_normal_ = {};
  h_texcoord_ = {};
  v_texcoord_ = {};
  h_color_ = {};
  v_color_ = {};
  h_tangent_ = {};
  h_texcoord1_ = {};
  computed_normals_ = false;
  follow_normals_ = false;
  const bool has_normal_attr =
      m.get_halfedge_property<Vec3>("h:normal") || m.get_vertex_property<Vec3>("v:normal");
  NormalSource ns = options_.normals;
  if (ns == NormalSource::automatic) {
    follow_normals_ = has_normal_attr;
    ns = has_normal_attr ? NormalSource::attribute : NormalSource::computed;
  }
  if (ns == NormalSource::attribute) {
    h_normal_ = m.get_halfedge_property<Vec3>("h:normal");
    if (!h_normal_) v_normal_ = m.get_vertex_property<Vec3>("v:normal");
  } else if (ns == NormalSource::computed) {
    computed_normals_ = true;
  }
  if (options_.texcoords) {
    h_texcoord_ = m.get_halfedge_property<Vec2>("h:texcoord");
    if (!h_texcoord_) v_texcoord_ = m.get_vertex_property<Vec2>("v:texcoord");
  }
  if (options_.colors) {
    h_color_ = m.get_halfedge_property<Color>("h:color");
    if (!h_color_) v_color_ = m.get_vertex_property<Color>("v:color");
  }
  if (options_.tangents) h_tangent_ = m.get_halfedge_property<Vec4>("h:tangent");
  if (options_.texcoords1) h_texcoord1_ = m.get_halfedge_property<Vec2>("h:texcoord1");
}

void RenderBuffers::setup_layout() {
  VertexLayout l;
  l.interleaved = options_.interleaved;
  const bool present[kStreams] = {true,
                                  h_normal_ || v_normal_ || computed_normals_,
                                  h_texcoord_ || v_texcoord_,
                                  h_color_ || v_color_,
                                  static_cast<bool>(h_tangent_),
                                  static_cast<bool>(h_texcoord1_)};
  std::int32_t* offset[kStreams] = {&l.position, &l.normal, &l.texcoord, &l.color, &l.tangent, &l.texcoord1};
  std::uint32_t at = 0;
  for (int i = 0; i < kStreams; ++i) {
    if (!present[i]) {
      *offset[i] = -1;
      continue;
    }
    *offset[i] = l.interleaved ? static_cast<std::int32_t>(at) : 0;
    at += kStreamWidth[i];
  }
  // In a separate layout `stride` still counts the floats of one whole vertex over all streams.
  l.stride = at;
  layout_ = l;
}

// ---- Vertex data ----------------------------------------------------------------------------------
// The floats of one render vertex in interleaved order: the vertex-sourced ones of v, and the
// corner-sourced ones too when h (the half-edge entering the corner) is valid.
void RenderBuffers::fill_vertex(Vertex v, Halfedge h, float* out) const {
  const SurfaceMesh& m = *mesh_;
  const float sx = options_.flip_x ? -1.f : 1.f;
  const Vec3& p = m.position(v);
  std::uint32_t at = 0;
  out[at++] = sx * p.x;
  out[at++] = p.y;
  out[at++] = p.z;
  // An attribute from its corner property when the mesh has one (written only where h is valid),
  // else from the vertex; its `width` floats keep their room in the vertex either way.
  auto attribute = [&](std::int32_t offset, std::uint32_t width, const auto& corner, auto from_vertex,
                       auto write) {
    if (offset < 0) return;
    const bool from_corner = static_cast<bool>(corner);
    if (!from_corner || h.is_valid()) write(from_corner ? corner[h] : from_vertex(), out + at);
    at += width;
  };
  attribute(
      layout_.normal, 3, h_normal_, [&] { return v_normal_ ? v_normal_[v] : vertex_normal_[v.idx()]; },
      [&](const Vec3& n, float* o) {
        o[0] = sx * n.x;
        o[1] = n.y;
        o[2] = n.z;
      });
  attribute(
      layout_.texcoord, 2, h_texcoord_, [&] { return v_texcoord_[v]; },
      [](const Vec2& t, float* o) {
        o[0] = t.x;
        o[1] = t.y;
      });
  attribute(
      layout_.color, 4, h_color_, [&] { return v_color_[v]; },
      [](const Color& c, float* o) {
        o[0] = c.r;
        o[1] = c.g;
        o[2] = c.b;
        o[3] = c.a;
      });
  // Corner-only attributes: a vertex value is never asked for (the corner property exists).
  attribute(
      layout_.tangent, 4, h_tangent_, [] { return Vec4{}; },
      [&](const Vec4& t, float* o) {
        o[0] = sx * t.x;
        o[1] = t.y;
        o[2] = t.z;
        o[3] = sx * t.w;
      });
  attribute(
      layout_.texcoord1, 2, h_texcoord1_, [] { return Vec2{}; },
      [](const Vec2& t, float* o) {
        o[0] = t.x;
        o[1] = t.y;
      });
}

void RenderBuffers::read_vertex(Index rv, float* out) const {
  if (layout_.interleaved) {
    std::memcpy(out, streams_[0].data() + std::size_t(rv) * layout_.stride, layout_.stride * sizeof(float));
    return;
  }
  std::uint32_t at = 0;
  for (int s = 0; s < kStreams; ++s) {
    if (!stream_present(s)) continue;
    std::memcpy(out + at, streams_[s].data() + std::size_t(rv) * kStreamWidth[s],
                kStreamWidth[s] * sizeof(float));
    at += kStreamWidth[s];
  }
}

bool RenderBuffers::stream_present(int s) const {
  switch (s) {
    case 0:
      return true;
    case 1:
      return layout_.normal >= 0;
    case 2:
      return layout_.texcoord >= 0;
    case 3:
      return layout_.color >= 0;
    case 4:
      return layout_.tangent >= 0;
    default:
      return layout_.texcoord1 >= 0;
  }
}

std::uint32_t RenderBuffers::stored_width(int s) const {
  if (layout_.interleaved) return s == 0 ? layout_.stride : 0;
  return stream_present(s) ? kStreamWidth[s] : 0;
}

void RenderBuffers::resize_streams(std::size_t n) {
  for (int s = 0; s < kStreams; ++s)
    if (const std::uint32_t w = stored_width(s)) streams_[s].resize(n * w);
}

void RenderBuffers::grow_capacity(std::size_t& capacity, std::size_t n) {
  if (n <= capacity) return;
  capacity = grown_capacity(n, capacity);
  if (!building_) result_.resized = true;
}

void RenderBuffers::store_vertex(Index rv, const float* data) {
  if (layout_.interleaved) {
    std::memcpy(streams_[0].data() + std::size_t(rv) * layout_.stride, data, layout_.stride * sizeof(float));
  } else {
    std::uint32_t at = 0;
    for (int s = 0; s < kStreams; ++s) {
      if (!stream_present(s)) continue;
      std::memcpy(streams_[s].data() + std::size_t(rv) * kStreamWidth[s], data + at,
                  kStreamWidth[s] * sizeof(float));
      at += kStreamWidth[s];
    }
  }
}

void RenderBuffers::rewrite_vertex_data(Vertex v) {
  Floats old, now;
  for (Index rv = v_first_rv_[v.idx()]; rv != kInvalidIndex; rv = rv_next_[rv]) {
    read_vertex(rv, old.data());
    now = old;  // keeps the corner-sourced floats
    fill_vertex(v, Halfedge(), now.data());
    if (std::memcmp(old.data(), now.data(), layout_.stride * sizeof(float)) == 0) continue;
    store_vertex(rv, now.data());
    written_vertices_.push_back(rv);
  }
}

Index RenderBuffers::allocate_vertex() {
  Index rv;
  if (!free_vertices_.empty()) {
    rv = free_vertices_.back();
    free_vertices_.pop_back();
    return rv;
  }
  rv = static_cast<Index>(rv_vertex_.size());
  grow_capacity(vertex_capacity_, rv_vertex_.size() + 1);
  rv_vertex_.push_back(Vertex());
  rv_next_.push_back(kInvalidIndex);
  rv_refs_.push_back(0);
  resize_streams(rv_vertex_.size());
  return rv;
}

Index RenderBuffers::find_or_add_render_vertex(Halfedge corner) {
  const Vertex v = mesh_->to_vertex(corner);
  Floats want;
  fill_vertex(v, corner, want.data());
  Floats have;
  for (Index rv = v_first_rv_[v.idx()]; rv != kInvalidIndex; rv = rv_next_[rv]) {
    read_vertex(rv, have.data());
    if (std::memcmp(have.data(), want.data(), layout_.stride * sizeof(float)) == 0) return rv;
  }
  const Index rv = allocate_vertex();
  rv_vertex_[rv] = v;
  rv_refs_[rv] = 0;
  rv_next_[rv] = v_first_rv_[v.idx()];
  v_first_rv_[v.idx()] = rv;
  store_vertex(rv, want.data());
  if (!building_) written_vertices_.push_back(rv);
  return rv;
}

void RenderBuffers::unref_vertex(Index rv) {
  if (--rv_refs_[rv] > 0) return;
  const Vertex v = rv_vertex_[rv];
  Index* link = &v_first_rv_[v.idx()];
  while (*link != rv) link = &rv_next_[*link];
  *link = rv_next_[rv];
  rv_next_[rv] = kInvalidIndex;
  rv_vertex_[rv] = Vertex();
  free_vertices_.push_back(rv);
}

// ---- Faces (index slots: render_buffers_submesh.cpp) ------------------------------------------
void RenderBuffers::sync_face(Face f) {
  const SurfaceMesh& m = *mesh_;
  corners_.clear();
  for (Halfedge h : m.halfedges(f)) corners_.push_back(h);
  const std::size_t n = corners_.size();
  if (n < 3) {  // cannot happen in a valid mesh; keep the buffers sane anyway
    release_face(f);
    return;
  }
  const std::uint32_t count = static_cast<std::uint32_t>(n - 2);

  // Corner render vertices first: an unchanged corner finds its render vertex again.
  corner_rvs_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Index rv = find_or_add_render_vertex(corners_[i]);
    corner_rvs_[i] = rv;
    corner_rv_[corners_[i].idx()] = rv;
  }

  // Triangles in face-corner indices.
  tris_.clear();
  if (n == 3) {
    tris_.push_back({0, 1, 2});
  } else {
    points_.clear();
    for (Halfedge h : corners_) points_.push_back(to_double(m.position(m.to_vertex(h))));
    triangulate_polygon(points_, tris_);
  }
  new_indices_.clear();
  for (const auto& t : tris_) {
    const Index a = corner_rvs_[t[0]], b = corner_rvs_[t[1]], c = corner_rvs_[t[2]];
    if (options_.winding == Winding::ccw)
      new_indices_.insert(new_indices_.end(), {a, b, c});
    else
      new_indices_.insert(new_indices_.end(), {a, c, b});
  }
  SlotRange& s = face_slots_[f.idx()];
  const std::uint32_t region = wanted_region(f);
  const bool same_slots = s.count == count && face_region_[f.idx()] == region;
  if (same_slots &&
      std::equal(new_indices_.begin(), new_indices_.end(), indices_.begin() + 3 * std::size_t(s.first)))
    return;  // nothing changed (a render vertex made for a corner is then already in use)
  // New references first, so that a render vertex kept by the face is not freed on the way.
  for (Index rv : new_indices_) ++rv_refs_[rv];
  if (same_slots) {
    // Same slots: rewrite in place and release the old references.
    const std::size_t begin = 3 * std::size_t(s.first);
    for (std::size_t i = 0; i < new_indices_.size(); ++i) {
      const Index old = indices_[begin + i];
      indices_[begin + i] = new_indices_[i];
      unref_vertex(old);
    }
    mark_indices_written(static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(new_indices_.size()));
    return;
  }
  release_face(f);  // the face's corner count changed (or it is new): slots of the new size
  s.first = allocate_triangles(count, region);
  s.count = count;
  face_region_[f.idx()] = region;
  std::fill_n(triangle_face_.begin() + s.first, count, f.idx());
  std::copy(new_indices_.begin(), new_indices_.end(), indices_.begin() + 3 * std::size_t(s.first));
  mark_indices_written(3 * s.first, 3 * count);
}

// ---- Normals ----------------------------------------------------------------------------------------
void RenderBuffers::update_normal(Vertex w) {
  const SurfaceMesh& m = *mesh_;
  // Summed in increasing face order, as full_build() sums, so that both give the same bits.
  normal_faces_.clear();
  if (!m.is_isolated(w))
    for (Face f : m.faces(w)) normal_faces_.push_back(f);
  std::sort(normal_faces_.begin(), normal_faces_.end());
  Vec3d sum{0, 0, 0};
  for (Face f : normal_faces_) sum += face_normal_sum(m, f);
  vertex_normal_[w.idx()] = to_float(normalize(sum));
}

void RenderBuffers::follow_normal(Vertex w) {
  SurfaceMesh& m = *mesh_;
  if (m.is_isolated(w)) return;
  if (v_normal_) {
    update_normal(w);
    v_normal_[w] = vertex_normal_[w.idx()];
    if (h_tangent_)  // the corners' tangents follow the vertex's new normal
      for (Halfedge o : m.halfedges(w)) {
        const Halfedge c = SurfaceMesh::twin(o);
        if (!m.is_boundary(c)) h_tangent_[c] = orthogonal_tangent(h_tangent_[c], v_normal_[w]);
      }
    return;
  }
  // Corners that held one value form a group; each group gets the normalised sum of its faces.
  normal_groups_.clear();
  auto group = [&](const Vec3& n) {
    std::size_t g = 0;
    while (g < normal_groups_.size() && !(normal_groups_[g].first == n)) ++g;
    if (g == normal_groups_.size()) normal_groups_.push_back({n, Vec3d{0, 0, 0}});
    return g;
  };
  for (Halfedge o : m.halfedges(w)) {
    const Halfedge c = SurfaceMesh::twin(o);  // enters w: w's corner in face(c)
    if (!m.is_boundary(c)) normal_groups_[group(h_normal_[c])].second += face_normal_sum(m, m.face(c));
  }
  // Every corner's group is found by its old value before any corner is rewritten.
  normal_corner_group_.clear();
  for (Halfedge o : m.halfedges(w)) {
    const Halfedge c = SurfaceMesh::twin(o);
    if (!m.is_boundary(c)) normal_corner_group_.push_back(group(h_normal_[c]));
  }
  std::size_t i = 0;
  for (Halfedge o : m.halfedges(w)) {
    const Halfedge c = SurfaceMesh::twin(o);
    if (m.is_boundary(c)) continue;
    h_normal_[c] = to_float(normalize(normal_groups_[normal_corner_group_[i++]].second));
    if (h_tangent_) h_tangent_[c] = orthogonal_tangent(h_tangent_[c], h_normal_[c]);
  }
}

void RenderBuffers::seed_normals(const ChangeLog::Pending& p) {
  const SurfaceMesh& m = *mesh_;
  ++normal_generation_;
  auto seed = [&](Vertex w) {
    if (!w.is_valid() || m.is_deleted(w)) return;
    if (normal_stamp_[w.idx()] == normal_generation_) return;
    normal_stamp_[w.idx()] = normal_generation_;
    normal_seeds_.push_back(w);
  };
  normal_seeds_.clear();
  for (Vertex v : p.vertices) {
    if (m.is_deleted(v)) continue;
    seed(v);
    if (m.is_isolated(v)) continue;
    for (Face f : m.faces(v))
      for (Vertex w : m.vertices(f)) seed(w);
  }
  for (Face f : p.faces) {
    if (!m.is_deleted(f)) {
      for (Vertex w : m.vertices(f)) seed(w);
    } else if (f.idx() < face_slots_.size() && face_slots_[f.idx()].count > 0) {
      // A removed face cannot be walked any more; its old corners are in its index slots.
      const SlotRange& s = face_slots_[f.idx()];
      for (std::size_t i = 3 * std::size_t(s.first); i < 3 * std::size_t(s.first + s.count); ++i)
        seed(rv_vertex_[indices_[i]]);
    }
  }
}

// ---- Sync ---------------------------------------------------------------------------------------------
void RenderBuffers::grow_element_arrays() {
  const SurfaceMesh& m = *mesh_;
  if (v_first_rv_.size() < m.vertex_slots()) v_first_rv_.resize(m.vertex_slots(), kInvalidIndex);
  if (corner_rv_.size() < m.halfedge_slots()) corner_rv_.resize(m.halfedge_slots(), kInvalidIndex);
  if (face_slots_.size() < m.face_slots()) face_slots_.resize(m.face_slots());
  if (face_region_.size() < m.face_slots()) face_region_.resize(m.face_slots(), 0);
  if (computed_normals_ || follow_normals_) {
    if (vertex_normal_.size() < m.vertex_slots()) vertex_normal_.resize(m.vertex_slots());
    if (normal_stamp_.size() < m.vertex_slots()) normal_stamp_.resize(m.vertex_slots(), 0);
  }
}

void RenderBuffers::full_build() {
  const SurfaceMesh& m = *mesh_;
  check_submeshes();  // before anything is reset, so that a refusal leaves the buffers as they were
  attach_sources();
  setup_layout();
  for (auto& s : streams_) s.clear();
  rv_vertex_.clear();
  rv_next_.clear();
  rv_refs_.clear();
  free_vertices_.clear();
  v_first_rv_.assign(m.vertex_slots(), kInvalidIndex);
  corner_rv_.assign(m.halfedge_slots(), kInvalidIndex);
  face_slots_.assign(m.face_slots(), SlotRange{});
  face_region_.assign(m.face_slots(), 0);
  layout_regions();  // the index buffer's regions, one per submesh
  vertex_normal_.clear();
  normal_stamp_.clear();
  grow_element_arrays();
  building_ = true;

  // Reserve for the common case: about one render vertex per vertex, n - 2 triangles per face.
  indices_.reserve(indices_.size() + 3 * m.n_faces());
  rv_vertex_.reserve(m.n_vertices());
  for (int s = 0; s < kStreams; ++s) streams_[s].reserve(m.n_vertices() * stored_width(s));

  if (computed_normals_) {
    // One Newell normal per face, added to its corners in increasing face order.
    std::vector<Vec3d> sum(m.vertex_slots(), Vec3d{0, 0, 0});
    for (Face f : m.faces()) {
      const Vec3d n = face_normal_sum(m, f);
      for (Vertex v : m.vertices(f)) sum[v.idx()] += n;
    }
    for (Vertex v : m.vertices()) vertex_normal_[v.idx()] = to_float(normalize(sum[v.idx()]));
  }
  for (Face f : m.faces()) sync_face(f);
  building_ = false;
  regions_measured_ = false;  // measured by the first submesh()

  // A little room to grow after a full build; growth beyond it is geometric (grown_capacity).
  vertex_capacity_ = rv_vertex_.size() + rv_vertex_.size() / 16 + 64;
  index_capacity_ = indices_.size() + indices_.size() / 16 + 192;
  report_full();
  result_.faces_synced = m.n_faces();
}

void RenderBuffers::report_full() {
  result_ = {};
  result_.full = true;
  result_.resized = true;
  if (!rv_vertex_.empty())
    result_.vertex_ranges.push_back({0, static_cast<std::uint32_t>(rv_vertex_.size())});
  if (!indices_.empty()) result_.index_ranges.push_back({0, static_cast<std::uint32_t>(indices_.size())});
  result_.vertices_synced = rv_vertex_.size();
  result_.vertex_bytes = rv_vertex_.size() * layout_.stride * sizeof(float);
  result_.index_bytes = indices_.size() * sizeof(std::uint32_t);
}

const SyncResult& RenderBuffers::rebuild() {
  full_build();
  changes_.consume();
  full_pending_ = false;
  return result_;
}

const SyncResult& RenderBuffers::sync() {
  sync_changes();
  if (full_pending_ && !in_transaction()) {
    const std::size_t faces = result_.faces_synced;
    report_full();
    result_.faces_synced = faces;
    full_pending_ = false;
  }
  return result_;
}

void RenderBuffers::sync_changes() {
  result_ = {};
  if (in_transaction()) return;
  const ChangeLog::Pending p = changes_.pending();
  if (p.reset) {
    rebuild();
    return;
  }
  if (p.vertices.empty() && p.faces.empty()) {
    changes_.consume();
    return;
  }
  const SurfaceMesh& m = *mesh_;
  // The mesh gained submeshes since the regions were laid out ("f:submesh" added by an edit, as
  // solid fracture adds it for its caps): lay them out again, grouped by it.
  if (!f_submesh_ && m.get_face_property<std::int32_t>(kSubmeshProperty)) {
    rebuild();
    return;
  }
  grow_element_arrays();
  written_vertices_.clear();
  written_indices_.clear();

  // Moved vertices (and, with computed or following normals, every vertex whose normal was
  // recomputed, moved ones included): rewrite the vertex-sourced floats of their render vertices.
  const bool renormal = computed_normals_ || follow_normals_;
  if (renormal) seed_normals(p);
  if (computed_normals_)
    for (Vertex w : normal_seeds_) update_normal(w);
  if (follow_normals_)
    for (Vertex w : normal_seeds_)
      if (m.is_live(w)) follow_normal(w);
  for (Vertex v : renormal ? std::span<const Vertex>(normal_seeds_) : p.vertices)
    if (m.is_live(v)) rewrite_vertex_data(v);
  // Faces: removed ones free their slots first, so that new faces can reuse them. A polygon's
  // triangulation depends on its corner positions, so polygons about a moved vertex are redone.
  // Following corner normals (and the tangents made perpendicular to them) changed the corners of
  // every face about a seed.
  dirty_faces_.assign(p.faces.begin(), p.faces.end());
  if (follow_normals_ && (h_normal_ || h_tangent_))
    for (Vertex w : normal_seeds_)
      if (m.is_live(w) && !m.is_isolated(w))
        for (Face f : m.faces(w)) dirty_faces_.push_back(f);
  for (Vertex v : p.vertices) {
    if (!m.is_live(v) || m.is_isolated(v)) continue;
    for (Face f : m.faces(v))
      if (face_slots_[f.idx()].count > 1) dirty_faces_.push_back(f);
  }
  std::sort(dirty_faces_.begin(), dirty_faces_.end());
  dirty_faces_.erase(std::unique(dirty_faces_.begin(), dirty_faces_.end()), dirty_faces_.end());
  for (Face f : dirty_faces_)
    if (f.idx() < m.face_slots() && m.is_deleted(f)) release_face(f);
  for (Face f : dirty_faces_)
    if (m.is_live(f)) sync_face(f);
  result_.faces_synced = dirty_faces_.size();
  if (region_overflow_) {  // a submesh's region ran out of room: lay the regions out again
    rebuild();
    return;
  }
  grow_regions();
  changes_.consume();
  finish_result();
}

void RenderBuffers::finish_result() {
  std::sort(written_vertices_.begin(), written_vertices_.end());
  written_vertices_.erase(std::unique(written_vertices_.begin(), written_vertices_.end()),
                          written_vertices_.end());
  result_.vertices_synced = written_vertices_.size();
  for (std::uint32_t rv : written_vertices_) {
    auto& r = result_.vertex_ranges;
    if (!r.empty() && r.back().first + r.back().count == rv)
      ++r.back().count;
    else
      r.push_back({rv, 1});
  }
  result_.index_ranges = written_indices_;
  merge_ranges(result_.index_ranges);
  result_.vertex_bytes = written_vertices_.size() * layout_.stride * sizeof(float);
  std::size_t idx = 0;
  for (const SlotRange& r : result_.index_ranges) idx += r.count;
  result_.index_bytes = idx * sizeof(std::uint32_t);
}

void RenderBuffers::begin() { mesh_->changes().begin(changes_.id()); }

const SyncResult& RenderBuffers::commit() {
  if (!mesh_->changes().commit(changes_.id())) {  // an inner transaction, or none was open
    result_ = {};
    return result_;
  }
  return sync();
}

RenderRemap RenderBuffers::compact() {
  // Bring everything up to date first, so that the maps describe current buffers.
  if (!in_transaction()) sync();
  RenderRemap map;
  const std::size_t nv = rv_vertex_.size();
  map.vertices.assign(nv, kInvalidIndex);
  Index live = 0;
  Floats data;
  for (std::size_t rv = 0; rv < nv; ++rv) {
    if (!rv_vertex_[rv].is_valid()) continue;
    map.vertices[rv] = live;
    if (live != rv) {
      read_vertex(static_cast<Index>(rv), data.data());
      store_vertex(live, data.data());
      rv_vertex_[live] = rv_vertex_[rv];
      rv_refs_[live] = rv_refs_[rv];
      rv_next_[live] = rv_next_[rv];
    }
    ++live;
  }
  rv_vertex_.resize(live);
  rv_refs_.resize(live);
  rv_next_.resize(live);
  for (Index& n : rv_next_)
    if (n != kInvalidIndex) n = map.vertices[n];
  for (Index& f : v_first_rv_)
    if (f != kInvalidIndex) f = map.vertices[f];
  for (Index& c : corner_rv_)
    if (c != kInvalidIndex) c = c < nv ? map.vertices[c] : kInvalidIndex;
  resize_streams(live);
  free_vertices_.clear();

  pack_triangles(map);        // triangles region by region
  regions_measured_ = false;  // measured by the first submesh()
  report_full();
  full_pending_ = true;
  return map;
}

}  // namespace hedge
