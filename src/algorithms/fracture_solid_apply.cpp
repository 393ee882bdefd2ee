// Solid fracture: a computed strike applied: the pieces get their properties, the mesh its patch.
#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>

#include "fracture_solid_strike.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/core/operations.h"
#include "hedge/core/threads.h"
#include "hedge/error.h"

namespace hedge::solid_detail {

namespace {

constexpr const char* kTexcoord = "h:texcoord";
constexpr const char* kCornerNormal = "h:normal";

//! Barycentric weights of x in triangle (a, b, c), clamped to the triangle.
std::array<float, 3> barycentric(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& x) {
  const Vec3d n = cross(b - a, c - a);
  const double nn = dot(n, n);
  if (!(nn > 0)) return {1.0f / 3, 1.0f / 3, 1.0f / 3};
  double wa = dot(cross(c - b, x - b), n) / nn, wb = dot(cross(a - c, x - c), n) / nn;
  double wc = 1 - wa - wb;
  wa = std::max(0.0, wa);
  wb = std::max(0.0, wb);
  wc = std::max(0.0, wc);
  const double s = wa + wb + wc;
  if (!(s > 0)) return {1.0f / 3, 1.0f / 3, 1.0f / 3};
  return {float(wa / s), float(wb / s), float(wc / s)};
}

//! Where a keyed point's vertex properties come from: mesh vertices and weights (n = 0: none).
struct Blend {
  Index src[3];
  float w[3];
  std::size_t n = 0;
};

Blend vertex_blend(const Geometry& g, const Key& k, const Vec3d& x) {
  Blend b;
  if (k.kind == Key::vertex) {
    b.src[0] = k.a;
    b.w[0] = 1;
    b.n = 1;
  } else if (k.kind == Key::edge) {
    const Vec3d pa = g.vertex(k.a), pb = g.vertex(k.b);
    const double l2 = dot(pb - pa, pb - pa);
    const double t = l2 > 0 ? std::clamp(dot(x - pa, pb - pa) / l2, 0.0, 1.0) : 0.5;
    b.src[0] = k.a;
    b.src[1] = k.b;
    b.w[0] = float(1 - t);
    b.w[1] = float(t);
    b.n = 2;
  } else if (k.kind == Key::triangle) {
    const SoupTriangle& s = (*g.soup)[k.a];
    const auto w = barycentric(g.vertex(s.v[0]), g.vertex(s.v[1]), g.vertex(s.v[2]), x);
    for (int i = 0; i < 3; ++i) {
      b.src[i] = s.v[i];
      b.w[i] = w[i];
    }
    b.n = 3;
  }
  return b;
}

//! dst[di] = blend of src's elements, across two containers: the sources are copied into scratch
//! elements past `base` (dst's size), blended, and the scratch dropped.
void blend_across(PropertyContainer& dst, std::size_t base, std::size_t di, const PropertyContainer& src,
                  const Index* s, const float* w, std::size_t n, const BasePropertyArray* skip) {
  dst.resize(base + n);
  Index idx[3];
  for (std::size_t k = 0; k < n; ++k) {
    dst.copy_element_from(src, s[k], base + k);
    idx[k] = static_cast<Index>(base + k);
  }
  dst.interpolate(di, idx, w, n, skip);
  dst.resize(base);
}

//! Planar texture coordinates of x on a cap of `plane`: model units in the plane's frame.
Vec2 cap_uv(const Plane& plane, const Vec3d& x) {
  Vec3d u, v;
  plane_frame(normalize(plane.n), u, v);
  return {float(dot(x, u)), float(dot(x, v))};
}

//! The unit normal of a cap on `plane` pointing out of cell `cell`'s piece: a cell lies below a
//! plane of the region, and below the bisector of break points i < j when it is i's.
Vec3 cap_normal(const PlaneSet& planes, std::uint32_t plane, std::size_t cell) {
  const Vec3d n = normalize(planes.planes[plane].n);
  const std::int64_t i = planes.pair_of[plane].first;
  return to_float(i < 0 || std::size_t(i) == cell ? n : -n);
}

//! Corner normals blended at a new point are made unit again (a zero one stays zero).
void renormalize(HalfedgeProperty<Vec3> normal, Halfedge h) {
  const Vec3 n = normal[h];
  const float l = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  if (l > 0) normal[h] = n * (1 / l);
}

//! Properties of a face the patch adds: a cap's marks and UVs, or those of its source face.
void set_patch_face_properties(SurfaceMesh& m, const Geometry& g, const Strike& strike, std::uint32_t from,
                               Face f, std::int32_t inner) {
  if (from & kCapBit) {
    m.face_property<std::uint8_t>(kInnerProperty, 0)[f] = 1;
    m.face_property<std::int32_t>(kSubmeshProperty, 0)[f] = inner;
    if (HalfedgeProperty<Vec2> uv = m.get_halfedge_property<Vec2>(kTexcoord))
      for (Halfedge h : m.halfedges(f))
        uv[h] = cap_uv(strike.planes.planes[from & ~kCapBit], to_double(m.position(m.to_vertex(h))));
    // The remaining object lies outside the region: its caps face into it, flat as a cut is.
    if (HalfedgeProperty<Vec3> normal = m.get_halfedge_property<Vec3>(kCornerNormal)) {
      const Vec3 n = -cap_normal(strike.planes, from & ~kCapBit, kSolidRemaining);
      for (Halfedge h : m.halfedges(f)) normal[h] = n;
    }
    return;
  }
  const SoupTriangle& st = strike.soup[from];
  m.face_properties().copy(st.face.idx(), f.idx());
  if (m.halfedge_properties().array_count() == 0) return;
  const Vec3d a = g.vertex(st.v[0]), b = g.vertex(st.v[1]), c = g.vertex(st.v[2]);
  const Index src[3] = {st.corner[0].idx(), st.corner[1].idx(), st.corner[2].idx()};
  const HalfedgeProperty<Vec3> normal = m.get_halfedge_property<Vec3>(kCornerNormal);
  for (Halfedge h : m.halfedges(f)) {
    const auto w = barycentric(a, b, c, to_double(m.position(m.to_vertex(h))));
    m.halfedge_properties().interpolate(h.idx(), src, w.data(), 3);
    if (normal) renormalize(normal, h);
  }
}

}  // namespace

std::int32_t inner_submesh_of(const SurfaceMesh& mesh, std::int32_t option) {
  if (option >= 0) return option;
  const FaceProperty<std::int32_t> submesh = mesh.get_face_property<std::int32_t>(kSubmeshProperty);
  if (!submesh) return 1;
  std::int32_t largest = 0;
  for (Face f : mesh.faces()) largest = std::max(largest, submesh[f]);
  if (largest == std::numeric_limits<std::int32_t>::max())
    throw InvalidInputError(
        "fracture_solid: the mesh's largest \"f:submesh\" is the largest int32; give inner_submesh "
        "explicitly");
  return largest + 1;
}

std::vector<SolidPiece> assemble_pieces(const StrikeInput& in, Strike& strike, std::int32_t inner) {
  const SurfaceMesh& m = in.mesh;
  const Geometry g{&m, &strike.planes, &strike.soup, nullptr};
  std::vector<SolidPiece> pieces;
  pieces.reserve(strike.pieces.size());
  for (PieceDraft& d : strike.pieces) {
    SolidPiece piece;
    piece.mesh = std::move(d.mesh);
    SurfaceMesh& out = piece.mesh;
    out.vertex_properties().add_missing_from(m.vertex_properties());
    out.halfedge_properties().add_missing_from(m.halfedge_properties());
    out.face_properties().add_missing_from(m.face_properties());
    FaceProperty<std::uint8_t> inner_mark = out.face_property<std::uint8_t>(kInnerProperty, 0);
    FaceProperty<std::int32_t> submesh = out.face_property<std::int32_t>(kSubmeshProperty, 0);
    HalfedgeProperty<Vec2> uv = out.get_halfedge_property<Vec2>(kTexcoord);
    HalfedgeProperty<Vec3> normal = out.get_halfedge_property<Vec3>(kCornerNormal);
    const BasePropertyArray* positions = out.positions().array();
    const KeyedSurface& s = d.surface;
    // build() keeps the input's order: point i is vertex i, triangle i face i.
    const std::size_t nv = out.vertex_slots();
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const Blend b = vertex_blend(g, s.points[i].first, s.points[i].second);
      if (b.n)
        blend_across(out.vertex_properties(), nv, i, m.vertex_properties(), b.src, b.w, b.n, positions);
    }
    const std::size_t nh = out.halfedge_slots();
    for (std::size_t i = 0; i < s.tris.size(); ++i) {
      const Face f(static_cast<Index>(i));
      const std::uint32_t from = s.source[i];
      if (from & kCapBit) {
        inner_mark[f] = 1;
        submesh[f] = inner;
        if (uv)
          for (Halfedge h : out.halfedges(f))
            uv[h] = cap_uv(strike.planes.planes[from & ~kCapBit], s.points[out.to_vertex(h).idx()].second);
        // Flat, as a cut is: the plane's normal out of the piece.
        if (normal) {
          const Vec3 n = cap_normal(strike.planes, from & ~kCapBit, d.cell);
          for (Halfedge h : out.halfedges(f)) normal[h] = n;
        }
        continue;
      }
      const SoupTriangle& st = strike.soup[from];
      out.face_properties().copy_element_from(m.face_properties(), st.face.idx(), f.idx());
      if (m.halfedge_properties().array_count() == 0) continue;
      const Vec3d a = g.vertex(st.v[0]), b = g.vertex(st.v[1]), c = g.vertex(st.v[2]);
      const Index src[3] = {st.corner[0].idx(), st.corner[1].idx(), st.corner[2].idx()};
      for (Halfedge h : out.halfedges(f)) {
        const auto w = barycentric(a, b, c, s.points[out.to_vertex(h).idx()].second);
        blend_across(out.halfedge_properties(), nh, h.idx(), m.halfedge_properties(), src, w.data(), 3,
                     nullptr);
        if (normal) renormalize(normal, h);
      }
    }
    // Of the cap faces as built (float positions), so it is what a caller measures on the mesh.
    piece.cap_area = 0;
    for (Face f : out.faces())
      if (inner_mark[f]) piece.cap_area += face_area(out, f);
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

void apply_remaining(const StrikeInput& in, Strike& strike, std::int32_t inner) {
  SurfaceMesh& m = in.mesh;
  const Geometry g{&m, &strike.planes, &strike.soup, nullptr};
  m.face_property<std::uint8_t>(kInnerProperty, 0);
  m.face_property<std::int32_t>(kSubmeshProperty, 0);
  const BasePropertyArray* positions = m.positions().array();
  // Removed elements keep their property values in storage (until garbage_collection()), so the
  // new ones are interpolated from them after the removal.
  remove_faces(m, strike.touched);
  const KeyedSurface& s = strike.patch;
  std::vector<Vertex> vert(s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const auto& [k, x] = s.points[i];
    if (k.kind == Key::vertex && !m.is_deleted(Vertex(k.a))) {
      vert[i] = Vertex(k.a);
      continue;
    }
    const Vertex v = m.add_vertex(k.kind == Key::vertex ? m.position(Vertex(k.a)) : to_float(x));
    const Blend b = vertex_blend(g, k, x);
    if (b.n) m.vertex_properties().interpolate(v.idx(), b.src, b.w, b.n, positions);
    vert[i] = v;
  }
  // The patch is linked in directly: a new edge for each pair of its half-edges, the rim's
  // half-edges (left without a face by the removal) for its edges on the rim. patch_outside()
  // checked that this makes the mesh closed and manifold there. (add_face() could not do it face
  // by face: where the region makes a tube, the last faces would join two rims at a vertex only.)
  const std::size_t n = s.tris.size();
  std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, Halfedge>>
      half;  // directed edge -> half-edge
  std::vector<std::array<std::uint32_t, 3>> idx(n);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) idx[i][k] = s.index(s.tris[i][k]);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) half.push_back({{idx[i][k], idx[i][(k + 1) % 3]}, Halfedge()});
  std::sort(half.begin(), half.end());
  auto find = [&](std::uint32_t a, std::uint32_t b) {
    const auto it =
        std::lower_bound(half.begin(), half.end(), std::make_pair(std::make_pair(a, b), Halfedge()),
                         [](const auto& x, const auto& y) { return x.first < y.first; });
    return it != half.end() && it->first == std::make_pair(a, b) ? it : half.end();
  };
  for (auto& [ab, h] : half) {
    if (h.is_valid()) continue;
    const auto twin = find(ab.second, ab.first);
    if (twin != half.end()) {
      h = m.new_edge(vert[ab.first], vert[ab.second]);
      twin->second = SurfaceMesh::twin(h);
    } else {
      h = m.find_halfedge(vert[ab.first], vert[ab.second]);
      if (!h.is_valid() || !m.is_boundary(h))
        throw std::logic_error("fracture_solid: the patch lost its rim");  // checked before: never
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Face f = m.new_face();
    std::array<Halfedge, 3> hs;
    for (int k = 0; k < 3; ++k) hs[k] = find(idx[i][k], idx[i][(k + 1) % 3])->second;
    for (int k = 0; k < 3; ++k) {
      m.set_next(hs[k], hs[(k + 1) % 3]);
      m.set_face(hs[k], f);
      m.set_halfedge(vert[idx[i][k]], hs[k]);
    }
    m.set_halfedge(f, hs[0]);
    m.mark_changed(f, ChangeEvent::faces_added);
    set_patch_face_properties(m, g, strike, s.source[i], f, inner);
  }
  for (std::size_t i = 0; i < vert.size(); ++i) m.adjust_outgoing_halfedge(vert[i]);
}

namespace {

void measure_piece(SolidPiece& p, const SolidFractureOptions& o) {
  try {
    p.mass = mass_properties(p.mesh, o.density);
  } catch (const InvalidInputError&) {
    p.mass = MassProperties{};
  }
  p.volume = p.mass.volume;
  p.centroid = p.mass.centre_of_mass;
  if (o.hulls) {
    std::vector<Vec3> points;
    points.reserve(p.mesh.n_vertices());
    for (Vertex v : p.mesh.vertices()) points.push_back(p.mesh.position(v));
    p.hull = convex_hull(points, o.hull_options);
  }
}

//! The fewest pieces worth a thread of their own: a piece's hull and mass take some hundreds of
//! microseconds, a thread some tens.
constexpr std::size_t kPiecesPerThread = 4;

}  // namespace

void measure_pieces(std::vector<SolidPiece>& pieces, const SolidFractureOptions& o,
                    const std::function<void()>& beside) {
  // Each piece is measured on its own, so the pieces are tasks on the workers (core/threads.h),
  // `beside` the first of them, each task writing only its own piece: the result does not depend
  // on the number of threads. What a task throws is thrown once every thread has finished:
  // beside's, else the first piece's.
  const std::size_t first = beside ? 1 : 0;
  std::vector<std::exception_ptr> error(pieces.size() + first);
  // Some pieces are worth a thread; beside counts as that many.
  const std::size_t threads =
      detail::parallel_parts(pieces.size() + first * kPiecesPerThread, kPiecesPerThread);
  detail::parallel_tasks(
      error.size(),
      [&](std::size_t task, std::size_t) {
        try {
          if (task < first)
            beside();
          else
            measure_piece(pieces[task - first], o);
        } catch (...) {
          error[task] = std::current_exception();
        }
      },
      threads);
  for (const std::exception_ptr& e : error)
    if (e) std::rethrow_exception(e);
}

}  // namespace hedge::solid_detail
