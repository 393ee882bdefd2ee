// RenderBuffers' index slots, grouped by submesh: see include/hedge/render/render_buffers.h.
//
// The index buffer is cut into one region of triangle slots per submesh, in submesh order. A face
// takes its slots from its submesh's region: a free run of its size if the region has one, else the
// region's untouched room. The last region has no end: it grows with the buffer, as a buffer of one
// submesh always did. A region with no room left lends slots at the buffer's end for the rest of the
// sync and asks for a full rebuild at its end, which lays the regions out again, each with room.
#include <algorithm>
#include <string>

#include "hedge/error.h"
#include "hedge/render/render_buffers.h"

namespace hedge {

namespace {
// Spare triangle slots a region of n triangles gets at a full build.
std::uint32_t spare_room(std::uint32_t n) { return n / 16 + 16; }
}  // namespace

std::uint32_t RenderBuffers::wanted_region(Face f) const {
  if (!f_submesh_) return 0;
  const std::int32_t s = f_submesh_[f];
  return s < 0 ? 0u : static_cast<std::uint32_t>(s);
}

void RenderBuffers::check_submeshes() const {
  const SurfaceMesh& m = *mesh_;
  const auto submesh = m.get_face_property<std::int32_t>(kSubmeshProperty);
  if (!submesh) return;
  for (Face f : m.faces())
    if (submesh[f] > kMaxSubmesh)
      throw InvalidInputError("render buffers: face " + std::to_string(f.idx()) + " has submesh " +
                              std::to_string(submesh[f]) + ", above the largest allowed, " +
                              std::to_string(kMaxSubmesh));
}

void RenderBuffers::layout_regions() {
  const SurfaceMesh& m = *mesh_;
  f_submesh_ = m.get_face_property<std::int32_t>(kSubmeshProperty);
  std::vector<std::uint32_t> count(1, 0);
  if (f_submesh_)  // without submeshes, the one region needs no count
    for (Face f : m.faces()) {
      const std::uint32_t r = wanted_region(f);
      if (r >= count.size()) count.resize(r + 1, 0);
      count[r] += static_cast<std::uint32_t>(m.valence(f) - 2);
    }
  regions_.assign(count.size(), Region{});
  free_triangles_.assign(count.size(), {});
  std::uint32_t at = 0;
  for (std::size_t r = 0; r + 1 < count.size(); ++r) {
    regions_[r].first = at;
    regions_[r].capacity = count[r] + spare_room(count[r]);
    at += regions_[r].capacity;
  }
  regions_.back().first = at;
  // Every slot of the bounded regions starts free and degenerate; sync_face() takes them in order.
  indices_.assign(3 * std::size_t(at), 0u);
  triangle_face_.assign(at, kInvalidIndex);
  free_triangle_slots_ = at;
  region_overflow_ = false;
}

std::uint32_t RenderBuffers::allocate_triangles(std::uint32_t count, std::uint32_t r) {
  if (r >= regions_.size()) {  // a submesh beyond the last region: lend slots, rebuild at the end
    region_overflow_ = true;
    r = static_cast<std::uint32_t>(regions_.size() - 1);
  }
  auto& lists = free_triangles_[r];
  if (count < lists.size() && !lists[count].empty()) {
    const std::uint32_t first = lists[count].back();
    lists[count].pop_back();
    free_triangle_slots_ -= count;
    return first;
  }
  Region& g = regions_[r];
  const bool last = r + 1 == regions_.size();
  if (!last && g.used + count <= g.capacity) {
    const std::uint32_t first = g.first + g.used;
    g.used += count;
    free_triangle_slots_ -= count;
    return first;
  }
  if (!last) region_overflow_ = true;  // the slots at the end are lent until the rebuild
  const std::uint32_t first = static_cast<std::uint32_t>(triangle_slots());
  const std::size_t n = indices_.size() + 3 * std::size_t(count);
  grow_capacity(index_capacity_, n);
  indices_.resize(n, 0);
  triangle_face_.resize(triangle_slots(), kInvalidIndex);
  regions_.back().capacity = static_cast<std::uint32_t>(triangle_slots()) - regions_.back().first;
  regions_.back().used = regions_.back().capacity;
  return first;
}

void RenderBuffers::free_triangles(std::uint32_t first, std::uint32_t count, std::uint32_t r) {
  // The triangles stay in the buffer as degenerate ones until they are reused or compacted.
  std::fill_n(indices_.begin() + 3 * std::size_t(first), 3 * std::size_t(count), 0u);
  std::fill_n(triangle_face_.begin() + first, count, kInvalidIndex);
  mark_indices_written(3 * first, 3 * count);
  auto& lists = free_triangles_[std::min<std::size_t>(r, free_triangles_.size() - 1)];
  if (lists.size() <= count) lists.resize(count + 1);
  lists[count].push_back(first);
  free_triangle_slots_ += count;
}

void RenderBuffers::mark_indices_written(std::uint32_t first, std::uint32_t count) {
  if (!building_ && count > 0) written_indices_.push_back({first, count});
}

void RenderBuffers::release_face(Face f) {
  SlotRange& s = face_slots_[f.idx()];
  if (s.count == 0) return;
  const std::size_t begin = 3 * std::size_t(s.first), end = begin + 3 * std::size_t(s.count);
  for (std::size_t i = begin; i < end; ++i) unref_vertex(indices_[i]);
  free_triangles(s.first, s.count, face_region_[f.idx()]);
  s = {};
}

void RenderBuffers::pack_triangles(RenderRemap& map) {
  map.triangles.assign(triangle_slots(), kInvalidIndex);
  std::vector<std::pair<std::uint32_t, Index>> order;  // (first slot, face)
  for (std::size_t f = 0; f < face_slots_.size(); ++f)
    if (face_slots_[f].count > 0) order.push_back({face_slots_[f].first, static_cast<Index>(f)});
  std::sort(order.begin(), order.end());  // regions are in submesh order, so this groups by region
  std::vector<std::uint32_t> packed;
  packed.reserve(3 * n_triangles());
  triangle_face_.clear();
  free_triangle_slots_ = 0;
  std::size_t next = 0;
  for (std::size_t r = 0; r < regions_.size(); ++r) {
    Region& g = regions_[r];
    g.first = static_cast<std::uint32_t>(packed.size() / 3);
    for (; next < order.size() && face_region_[order[next].second] == r; ++next) {
      const auto [first, f] = order[next];
      SlotRange& s = face_slots_[f];
      const std::uint32_t to = static_cast<std::uint32_t>(packed.size() / 3);
      for (std::uint32_t t = 0; t < s.count; ++t) {
        map.triangles[first + t] = to + t;
        triangle_face_.push_back(f);
        for (int k = 0; k < 3; ++k) packed.push_back(map.vertices[indices_[3 * std::size_t(first + t) + k]]);
      }
      s.first = to;
    }
    g.used = static_cast<std::uint32_t>(packed.size() / 3) - g.first;
    g.capacity = g.used;
    if (r + 1 < regions_.size()) {  // room to grow, as a full build leaves
      const std::uint32_t spare = spare_room(g.used);
      packed.resize(packed.size() + 3 * std::size_t(spare), 0u);
      triangle_face_.resize(triangle_face_.size() + spare, kInvalidIndex);
      g.capacity += spare;
      free_triangle_slots_ += spare;
    }
  }
  indices_.swap(packed);
  for (auto& lists : free_triangles_) lists.clear();
}

SubmeshRange RenderBuffers::submesh(std::size_t i) const {
  if (i >= regions_.size())
    throw InvalidInputError("render buffers: submesh " + std::to_string(i) + " of " +
                            std::to_string(regions_.size()));
  const Region& g = regions_[i];
  const std::uint32_t slots =
      i + 1 == regions_.size() ? static_cast<std::uint32_t>(triangle_slots()) - g.first : g.capacity;
  if (!regions_measured_) {
    measure_regions();
    regions_measured_ = true;
  }
  SubmeshRange out;
  out.index_start = 3 * g.first;
  out.index_count = 3 * slots;
  if (g.has_vertices && slots > 0) {
    out.first_vertex = g.vertex_lo;
    out.vertex_count = g.vertex_hi - g.vertex_lo + 1;
  }
  if (g.has_box) {
    out.min = g.box_lo;
    out.max = g.box_hi;
  }
  return out;
}

std::uint32_t RenderBuffers::region_of_slot(std::uint32_t t) const {
  const auto after = std::upper_bound(regions_.begin(), regions_.end(), t,
                                      [](std::uint32_t slot, const Region& g) { return slot < g.first; });
  return static_cast<std::uint32_t>(after - regions_.begin()) - 1;
}

void RenderBuffers::include_in_region(const Region& g, std::uint32_t rv, bool live) const {
  g.vertex_lo = g.has_vertices ? std::min(g.vertex_lo, rv) : rv;
  g.vertex_hi = g.has_vertices ? std::max(g.vertex_hi, rv) : rv;
  g.has_vertices = true;
  if (!live) return;
  const float* q = streams_[0].data() + std::size_t(rv) * (layout_.interleaved ? layout_.stride : 3);
  if (!g.has_box) g.box_lo = g.box_hi = Vec3{q[0], q[1], q[2]};
  g.box_lo = {std::min(g.box_lo.x, q[0]), std::min(g.box_lo.y, q[1]), std::min(g.box_lo.z, q[2])};
  g.box_hi = {std::max(g.box_hi.x, q[0]), std::max(g.box_hi.y, q[1]), std::max(g.box_hi.z, q[2])};
  g.has_box = true;
}

void RenderBuffers::measure_regions() const {
  for (std::size_t r = 0; r < regions_.size(); ++r) {
    const Region& g = regions_[r];
    g.has_vertices = g.has_box = false;
    const std::size_t end = r + 1 == regions_.size() ? triangle_slots() : g.first + g.capacity;
    for (std::size_t t = g.first; t < end; ++t)
      for (int k = 0; k < 3; ++k)
        include_in_region(g, indices_[3 * t + k], triangle_face_[t] != kInvalidIndex);
  }
}

void RenderBuffers::grow_regions() {
  if (!regions_measured_) return;  // the first submesh() measures them all
  for (const SlotRange& w : written_indices_)
    for (std::uint32_t k = w.first; k < w.first + w.count; ++k) {
      const std::uint32_t t = k / 3;
      include_in_region(regions_[region_of_slot(t)], indices_[k], triangle_face_[t] != kInvalidIndex);
    }
  // A rewritten render vertex (moved, or given a new normal) is in the regions of its vertex's faces;
  // every render vertex of one mesh vertex has the same position, so growing by it is exact.
  const SurfaceMesh& m = *mesh_;
  for (std::uint32_t rv : written_vertices_) {
    const Vertex v = rv_vertex_[rv];
    if (!v.is_valid() || !m.is_live(v) || m.is_isolated(v)) continue;
    for (Face f : m.faces(v))
      if (face_slots_[f.idx()].count > 0) include_in_region(regions_[face_region_[f.idx()]], rv, true);
  }
}

}  // namespace hedge
