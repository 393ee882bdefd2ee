// Solid fracture: one strike computed without touching the mesh: the cells, each piece clipped and
// capped, and the patch of the remaining object.
#include "fracture_solid_strike.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <span>

#include "core_private/link_closed.h"
#include "fracture_solid_soup.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/core/threads.h"
#include "hedge/core/triangulate.h"
#include "hedge/error.h"

namespace hedge::solid_detail {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point& t) {
  const Clock::time_point now = Clock::now();
  const double s = std::chrono::duration<double>(now - t).count();
  t = now;
  return s;
}

//! Whether p lies inside the closed mesh: the first triangle a fixed ray from p meets is seen from
//! behind. The hit triangle's own normal decides, not its face's: a non-planar polygon's triangles
//! may point apart from the polygon's mean normal. O(log n).
bool inside_mesh(const StrikeInput& in, const Vec3d& p) {
  const Vec3 dir = to_float(normalize(Vec3d{0.5773, 0.6412, 0.5061}));
  const std::optional<RayHit> hit = in.tree.first_hit(to_float(p), dir);
  if (!hit) return false;
  const Vec3d a = to_double(in.mesh.position(hit->corners[0]));
  const Vec3d b = to_double(in.mesh.position(hit->corners[1]));
  const Vec3d c = to_double(in.mesh.position(hit->corners[2]));
  return dot(cross(b - a, c - a), to_double(dir)) > 0;
}

//! Clipped polygons, their storage kept from one polytope to the next: the first `size` are in use.
struct PolygonList {
  std::vector<ClipPolygon> store;
  std::size_t size = 0;
  void clear() { size = 0; }
  ClipPolygon& next() {
    if (size == store.size()) {
      ClipPolygon& p = store.emplace_back();
      p.keys.reserve(8);
      p.pos.reserve(8);
      p.support.reserve(8);
    }
    return store[size];
  }
  std::span<const ClipPolygon> view() const { return {store.data(), size}; }
};

//! Per soup vertex, the first half-space of the polytope at hand it lies outside of (the number of
//! half-spaces if none), computed once per polytope (stamped) with the test clip_triangle() makes;
//! and the soup triangles listed for the polytope's box so far (stamped too).
struct FirstOut {
  //! The polytope's half-spaces, and a copy of each one's plane (read without an indirection).
  std::vector<HalfSpace> planes;
  std::vector<Plane> plane;
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> stamp;
  std::vector<std::uint32_t> listed;
  std::vector<std::uint32_t> triangles;
  std::uint32_t current = 0;
};

//! The clipped polygons of the soup triangles in a convex polytope, in soup order: the triangles
//! whose boxes meet the polytope's box, found through the soup's grid, so a cell costs its own
//! triangles. Most of them lie wholly inside the polytope or outside one of its half-spaces: their
//! corners' classification (shared by the triangles around a vertex) decides them as
//! clip_triangle() would, and only the triangles a plane crosses are clipped.
void clip_all(const Geometry& g, const SoupIndex& index, const SoupGrid& grid, const Polytope& cell,
              double margin, FirstOut& masks, PolygonList& out) {
  float lo[3], hi[3];
  cell.box(margin, lo, hi);
  std::vector<HalfSpace>& planes = masks.planes;
  planes.clear();
  masks.plane.clear();
  for (const Polytope::Side& s : cell.faces) {
    planes.push_back(s.h);
    masks.plane.push_back(g.planes->planes[s.h.plane]);
  }
  if (masks.stamp.size() != index.vertices.size() || masks.listed.size() != index.corner.size()) {
    masks.stamp.assign(index.vertices.size(), 0);
    masks.first.assign(index.vertices.size(), 0);
    masks.listed.assign(index.corner.size(), 0);
    masks.current = 0;
  }
  ++masks.current;
  const std::uint32_t none = static_cast<std::uint32_t>(planes.size());
  auto first_out = [&](std::uint32_t v) {
    if (masks.stamp[v] != masks.current) {
      masks.stamp[v] = masks.current;
      const Vec3d p = g.vertex(index.vertices[v]);
      std::uint32_t k = 0;
      while (k < none && masks.plane[k].below(p) != planes[k].flip) ++k;
      masks.first[v] = k;
    }
    return masks.first[v];
  };
  // The triangles whose boxes meet the box, in soup order: the order the pieces' faces take.
  std::vector<std::uint32_t>& list = masks.triangles;
  list.clear();
  grid.for_buckets(lo, hi, [&](std::size_t b) {
    for (std::uint32_t i = grid.first[b]; i < grid.first[b + 1]; ++i) {
      const std::uint32_t t = grid.items[i];
      if (masks.listed[t] == masks.current || !overlaps((*g.soup)[t], lo, hi)) continue;
      masks.listed[t] = masks.current;
      list.push_back(t);
    }
  });
  if (list.size() * 8 >= index.corner.size()) {
    // Most of the soup (P's own box holds all of it): its listed triangles in order, by one pass.
    list.clear();
    for (std::uint32_t t = 0; t < index.corner.size(); ++t)
      if (masks.listed[t] == masks.current) list.push_back(t);
  } else {
    std::sort(list.begin(), list.end());
  }
  for (const std::uint32_t t : list) {
    const SoupTriangle& tri = (*g.soup)[t];
    const auto& c = index.corner[t];
    const std::uint32_t a = first_out(c[0]), b = first_out(c[1]), d = first_out(c[2]);
    if (a == none && b == none && d == none) {
      // Inside every half-space: clip_triangle() would return the triangle as it is.
      ClipPolygon& p = out.next();
      p.triangle = t;
      p.keys.clear();
      p.pos.clear();
      p.support.clear();
      for (int i = 0; i < 3; ++i) {
        p.keys.push_back({Key::vertex, tri.v[i], 0, 0});
        p.pos.push_back(g.vertex(tri.v[i]));
        p.support.push_back(kNoPlane);
      }
      ++out.size;
      continue;
    }
    // The first half-space a corner leaves is the first that changes the triangle (the corners
    // lie inside the ones before); when every corner leaves it, clip_triangle() would return
    // nothing.
    if (a == b && b == d) continue;
    // The half-spaces before the first one a corner leaves hold the whole triangle.
    ClipPolygon& poly = out.next();
    clip_triangle(g, t, planes, poly, std::min({a, b, d}));
    if (!poly.keys.empty()) ++out.size;
  }
}

//! The caps of a convex polytope: on each face, the part inside the mesh. Appends triangles
//! (counter-clockwise seen from outside the polytope) with their plane as source, and their area
//! per face.
bool cap_polytope(const StrikeInput& in, const Polytope& cell, std::span<const ClipPolygon> polys,
                  KeyedSurface& out, std::string& failure) {
  // The surface's edges on each plane, reversed: the caps' chains.
  std::vector<std::pair<std::uint32_t, ChainEdge>> on_plane;
  for (const ClipPolygon& p : polys) {
    const std::size_t n = p.keys.size();
    for (std::size_t i = 0; i < n; ++i)
      if (p.support[i] != kNoPlane) {
        const std::size_t j = (i + 1) % n;
        on_plane.push_back({p.support[i], {p.keys[j], p.keys[i], p.pos[j], p.pos[i]}});
      }
  }
  std::stable_sort(on_plane.begin(), on_plane.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t fi = 0; fi < cell.faces.size(); ++fi) {
    const Polytope::Side& f = cell.faces[fi];
    RegionInput r;
    for (const Key& k : f.corners) {
      r.corners.push_back(k);
      r.corner_pos.push_back(cell.at(k));
    }
    for (auto it = std::lower_bound(on_plane.begin(), on_plane.end(), f.h.plane,
                                    [](const auto&a, std::uint32_t plane) { return a.first < plane; });
         it != on_plane.end() && it->first == f.h.plane; ++it)
      r.chain.push_back(it->second);
    const std::size_t n = f.corners.size();
    std::vector<std::uint32_t> side_plane(n);
    for (std::size_t s = 0; s < n; ++s) {
      const Key& a = f.corners[s];
      const Key& b = f.corners[(s + 1) % n];
      side_plane[s] = kNoPlane;
      for (std::uint32_t q : {a.a, a.b, a.c})
        if (q != f.h.plane && (q == b.a || q == b.b || q == b.c)) side_plane[s] = q;
    }
    const std::uint32_t own = f.h.plane;
    r.side = [&](const Key& k) -> int {
      if (k.kind != Key::triangle || (k.b != own && k.c != own)) return -2;
      const std::uint32_t other = k.b == own ? k.c : k.b;
      for (std::size_t s = 0; s < n; ++s)
        if (side_plane[s] == other) return static_cast<int>(s);
      return -2;
    };
    const Key first = *std::min_element(f.corners.begin(), f.corners.end());
    r.inside = [&]() { return inside_mesh(in, cell.at(first)); };
    // The outward normal, for the frame of the triangulation.
    Vec3d normal{};
    for (std::size_t s = 0; s < n; ++s) add_newell_term(normal, r.corner_pos[s], r.corner_pos[(s + 1) % n]);
    r.normal = normalize(normal);
    std::vector<std::array<Key, 3>> tris;
    if (!fill_region(r, tris, out.points)) {
      failure = "a cap on plane " + std::to_string(own) + " did not close";
      return false;
    }
    for (const auto& t : tris) out.add(t, kCapBit | own);
  }
  return true;
}

}  // namespace

void KeyedSurface::finish_points(std::vector<std::uint32_t>* corner) {
  // Duplicates dropped through a table first (a point is listed once per polygon around it), so
  // that only the distinct ones are sorted; of equal keys the first listed stays (they are one
  // point, computed alike).
  KeyTable table(points.size());
  std::vector<std::pair<Key, std::uint32_t>> order;  // distinct keys, with their place in `points`
  order.reserve(points.size() / 2);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::uint32_t n = static_cast<std::uint32_t>(kept);
    if (table.find_or_add(points[i].first, n) != n) continue;
    points[kept++] = points[i];
    order.push_back({points[i].first, n});
  }
  points.resize(kept);
  std::sort(order.begin(), order.end());
  std::vector<std::pair<Key, Vec3d>> sorted(kept);
  std::vector<std::uint32_t> rank(kept);
  for (std::size_t r = 0; r < kept; ++r) {
    sorted[r] = points[order[r].second];
    rank[order[r].second] = static_cast<std::uint32_t>(r);
  }
  points = std::move(sorted);
  if (!corner) return;
  corner->resize(3 * tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t n = table.find(tris[t][k]);
      (*corner)[3 * t + k] = n == KeyTable::kAbsent ? KeyTable::kAbsent : rank[n];
    }
}

std::uint32_t KeyedSurface::index(const Key& k) const {
  const auto it =
      std::lower_bound(points.begin(), points.end(), k,
                       [](const std::pair<Key, Vec3d>& p, const Key& key) { return p.first < key; });
  return static_cast<std::uint32_t>(it - points.begin());
}

void region_faces(const StrikeInput& in, std::vector<Face>& faces) {
  // P lies within the cube of its six axis planes (its other planes cut that cube's edges and
  // corners off); the margin covers the nudge of a retry.
  const double r = in.region_radius * 1.0001;
  const Vec3d c = in.centre;
  in.tree.faces_in_box(to_float(c - Vec3d{r, r, r}), to_float(c + Vec3d{r, r, r}), faces);
}

bool build_closed(KeyedSurface& s, SurfaceMesh& mesh, std::vector<std::uint32_t>& corner,
                  std::string& failure) {
  using link_detail::ClosedLinkDefect;
  using Kind = ClosedLinkDefect::Kind;
  s.finish_points(&corner);
  const std::size_t nv = s.points.size();
  const ClosedLinkDefect d = link_detail::link_closed_triangles(corner, nv, mesh);
  auto edge = [&d] { return "the edge of points " + std::to_string(d.a) + " and " + std::to_string(d.b); };
  switch (d.kind) {
    case Kind::none:
    case Kind::several_fans:  // a point that is not finite is named first
      break;
    case Kind::vertex_out_of_range:
      failure = "a piece's triangle " + std::to_string(d.triangle) + " uses a point it does not list";
      return false;
    case Kind::repeated_vertex:
      failure = "a piece is not manifold: triangle " + std::to_string(d.triangle) + " repeats a point";
      return false;
    case Kind::edge_used_twice:
      failure = "a piece is not manifold: two of its triangles run along " + edge() + " the same way";
      return false;
    case Kind::open_edge:
      failure = "a piece is open: no triangle runs along " + edge() + " the other way";
      return false;
    case Kind::wrong_twin:
      failure = "a piece could not be linked: " + link_detail::describe(d);
      return false;
  }
  for (std::size_t v = 0; v < nv; ++v) {
    const Vec3 p = to_float(s.points[v].second);
    if (!is_finite(p)) {
      failure = "a piece's point " + std::to_string(v) + " is not finite";
      return false;
    }
    if (!d) mesh.position(Vertex(static_cast<Index>(v))) = p;
  }
  if (d) {
    failure =
        "a piece is not manifold: its faces around point " + std::to_string(d.a) + " form more than one fan";
    return false;
  }
  return true;
}

namespace {

//! Triangles of each clipped polygon (a fan: it is convex), with their soup triangle as source.
void add_polygons(std::span<const ClipPolygon> polys, KeyedSurface& s) {
  for (const ClipPolygon& p : polys) {
    for (std::size_t k = 1; k + 1 < p.keys.size(); ++k)
      s.add({p.keys[0], p.keys[k], p.keys[k + 1]}, p.triangle);
    for (std::size_t k = 0; k < p.keys.size(); ++k) s.points.emplace_back(p.keys[k], p.pos[k]);
  }
}

//! One cell's piece, made on a worker thread: its draft (closed) and its cap area per plane, or
//! the failure that stops the strike, or an exception to pass on.
struct CellWork {
  PieceDraft draft;
  bool made = false;
  std::string failure;
  std::exception_ptr error;
  std::vector<std::pair<std::uint32_t, double>> cap_area;
  double seconds_clip = 0, seconds_cap = 0;
};

//! A worker's scratch, kept from one cell to the next.
struct CellScratch {
  PolygonList polys;
  FirstOut masks;
  std::vector<std::uint32_t> corner;
};

void piece_of(const StrikeInput& in, const Geometry& g, const SoupIndex& index, const SoupGrid& grid,
              const Polytope& cell, double margin, CellScratch& scratch, CellWork& w) {
  if (cell.empty()) return;
  try {
    Clock::time_point t = Clock::now();
    scratch.polys.clear();
    clip_all(g, index, grid, cell, margin, scratch.masks, scratch.polys);
    w.seconds_clip += seconds_since(t);
    PieceDraft& d = w.draft;
    add_polygons(scratch.polys.view(), d.surface);
    if (!cap_polytope(in, cell, scratch.polys.view(), d.surface, w.failure)) return;
    if (d.surface.tris.empty()) {
      w.seconds_cap += seconds_since(t);
      return;
    }
    std::vector<std::uint32_t>& corner = scratch.corner;  // the piece's corners, as its points
    if (!build_closed(d.surface, d.mesh, corner, w.failure)) return;
    for (std::size_t k = 0; k < d.surface.tris.size(); ++k) {
      if (!(d.surface.source[k] & kCapBit)) continue;
      const Vec3d a = d.surface.points[corner[3 * k]].second;
      const Vec3d b = d.surface.points[corner[3 * k + 1]].second;
      const Vec3d c = d.surface.points[corner[3 * k + 2]].second;
      w.cap_area.emplace_back(d.surface.source[k] & ~kCapBit, triangle_area(a, b, c));
    }
    w.made = true;
    w.seconds_cap += seconds_since(t);
  } catch (...) {
    w.error = std::current_exception();
  }
}

//! The region's side of a strike, made on a worker beside the cells: whether the patch was made,
//! or the exception to pass on, and its thread time spent clipping and capping.
struct RegionWork {
  bool made = false;
  std::exception_ptr error;
  double seconds_clip = 0, seconds_cap = 0;
};

//! The patch of the remaining object: the touched triangles' parts outside P, and P's caps turned
//! inwards (patch_outside()). Writes strike.soup (patch_outside() may extend it), patch, touched and,
//! if the patch cannot be made, failure.
void region_patch(const StrikeInput& in, const Geometry& g, const SoupIndex& index, const SoupGrid& grid,
                  const Polytope& region, double margin, Strike& strike, RegionWork& w) {
  try {
    Clock::time_point t = Clock::now();
    PolygonList polys;
    FirstOut masks;
    clip_all(g, index, grid, region, margin, masks, polys);
    w.seconds_clip += seconds_since(t);
    KeyedSurface caps;
    if (!cap_polytope(in, region, polys.view(), caps, strike.failure)) return;
    for (std::size_t k = 0; k < caps.tris.size(); ++k) {
      const auto& tri = caps.tris[k];
      strike.patch.add({tri[0], tri[2], tri[1]}, caps.source[k]);
    }
    strike.patch.points = std::move(caps.points);
    // The caps are made: each polygon moves to its triangle's slot.
    std::vector<ClipPolygon> inside_p(strike.soup.size());
    std::vector<char> touched_tri(strike.soup.size(), 0);
    for (std::size_t i = 0; i < polys.size; ++i) {
      const std::uint32_t tri = polys.store[i].triangle;
      touched_tri[tri] = 1;
      inside_p[tri] = std::move(polys.store[i]);
    }
    if (!patch_outside(in, g, inside_p, touched_tri, strike)) return;
    strike.patch.finish_points();
    w.made = true;
    w.seconds_cap += seconds_since(t);
  } catch (...) {
    w.error = std::current_exception();
  }
}

}  // namespace

bool compute_strike(const StrikeInput& in, const std::vector<Face>& faces, double nudge, std::uint64_t seed,
                    Strike& strike) {
  Clock::time_point t = Clock::now();
  // Two independent tasks (core/threads.h): the cells, which add their bisectors to strike.planes
  // in cell order, and the soup with its index and grid.
  Polytope region;
  std::vector<Polytope> cells;
  bool cells_made = true;
  SoupIndex index;
  SoupGrid grid;
  std::exception_ptr error[2];
  detail::parallel_tasks(2, [&](std::size_t task, std::size_t) {
    try {
      if (task == 1) {
        strike.soup = make_soup(in.mesh, faces);
        index = index_soup(strike.soup);
        grid = grid_soup(strike.soup);
        return;
      }
      region = region_polytope(in.centre, in.region_radius, strike.planes, seed, nudge);
      const std::vector<Vec3d> points = break_points(in.material, in.centre, seed, nudge);
      cells.resize(points.size());
      for (std::uint32_t i = 0; i < points.size() && cells_made; ++i)
        cells_made = voronoi_cell(region, points, i, strike.planes, cells[i]);
    } catch (...) {
      error[task] = std::current_exception();
    }
  });
  if (error[0]) std::rethrow_exception(error[0]);
  if (!cells_made) {
    strike.failure = "a cell is degenerate";
    return false;
  }
  if (error[1]) std::rethrow_exception(error[1]);
  const double margin = 1e-6 * in.region_radius;
  // The region's patch may add triangles to strike.soup (patch_outside()) while the cells read it:
  // they read a copy.
  const std::vector<SoupTriangle> cell_soup = strike.soup;
  const Geometry g{&in.mesh, &strike.planes, &strike.soup, nullptr};
  const Geometry cell_g{&in.mesh, &strike.planes, &cell_soup, nullptr};
  strike.seconds_cells += seconds_since(t);

  // The region's patch and the cells are independent: each is clipped, capped and built as a task
  // on the workers (core/threads.h), the patch, the longest, first; each writes only its own
  // slot (the patch: strike's soup, patch, touched and failure), and the results are then taken in
  // cell order, so they do not depend on the number of threads.
  RegionWork region_work;
  std::vector<CellWork> work(cells.size());
  std::vector<CellScratch> scratch(detail::parallel_parts(cells.size() + 1, 1));
  detail::parallel_tasks(
      cells.size() + 1,
      [&](std::size_t task, std::size_t worker) {
        if (task == 0)
          region_patch(in, g, index, grid, region, margin, strike, region_work);
        else
          piece_of(in, cell_g, index, grid, cells[task - 1], margin, scratch[worker], work[task - 1]);
      },
      scratch.size());
  // Per plane and piece, the cap area, for the bonds.
  std::vector<std::pair<std::pair<std::size_t, std::uint32_t>, double>> cap_areas;
  double clip_cpu = region_work.seconds_clip, cap_cpu = region_work.seconds_cap;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    CellWork& w = work[i];
    if (w.error) std::rethrow_exception(w.error);
    clip_cpu += w.seconds_clip;
    cap_cpu += w.seconds_cap;
    if (!w.failure.empty()) {
      strike.failure = std::move(w.failure);
      return false;
    }
    if (!w.made) continue;
    w.draft.cell = i;
    strike.pieces.push_back(std::move(w.draft));
    for (const auto& [plane, ar] : w.cap_area) cap_areas.push_back({{strike.pieces.size() - 1, plane}, ar});
  }
  // The loop's wall time, split between clipping and capping as their thread times are.
  const double loop = seconds_since(t);
  const double share = clip_cpu + cap_cpu > 0 ? clip_cpu / (clip_cpu + cap_cpu) : 0.5;
  strike.seconds_clip += loop * share;
  strike.seconds_cap += loop * (1 - share);
  if (strike.pieces.empty()) {
    // No piece: nothing is broken, and the patch is not needed (nor its failure).
    strike.failure.clear();
    return true;
  }
  if (region_work.error) std::rethrow_exception(region_work.error);
  if (!region_work.made) return false;

  // Bonds: cap area on a bisector joins its two cells' pieces, on a plane of P the remaining object.
  std::sort(cap_areas.begin(), cap_areas.end());
  std::vector<std::size_t> piece_of_cell(cells.size(), kSolidRemaining);
  for (std::size_t p = 0; p < strike.pieces.size(); ++p) piece_of_cell[strike.pieces[p].cell] = p;
  std::map<std::pair<std::size_t, std::size_t>, double> bond;
  for (const auto& [key, ar] : cap_areas) {
    const auto [piece, plane] = key;
    const auto [i, j] = strike.planes.pair_of[plane];
    std::size_t other = kSolidRemaining;
    if (i >= 0) {
      const std::size_t cell = strike.pieces[piece].cell;
      other = piece_of_cell[static_cast<std::size_t>(cell == std::size_t(i) ? j : i)];
      if (other == kSolidRemaining || other < piece) continue;  // counted from the other end (or empty)
    }
    bond[{piece, other}] += ar;
  }
  for (const auto& [ab, ar] : bond)
    if (ar > 0) strike.bonds.push_back({ab.first, ab.second, ar});
  return true;
}

}  // namespace hedge::solid_detail
