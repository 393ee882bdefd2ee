// Fracture. See include/hedge/algorithms/fracture.h for the contract.
#include "hedge/algorithms/fracture.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <queue>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "format.h"
#include "hedge/algorithms/detach_faces.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/core/build.h"
#include "hedge/core/operations.h"
#include "hedge/error.h"

namespace hedge {

namespace {

using detail::number;

//! A barycentric weight this close to 1 (or to 0) puts the impact on a corner (or an edge).
constexpr double kSnap = 1e-3;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point& t) {
  const Clock::time_point now = Clock::now();
  const double s = std::chrono::duration<double>(now - t).count();
  t = now;
  return s;
}

//! Distances with the grain shortened: the component along `axis` counts `shrink` times.
struct Metric {
  Vec3d axis{};  // unit, or zero: isotropic
  double shrink = 1;
  double length(const Vec3d& d) const {
    const double a = dot(d, axis);
    const double perp2 = std::max(0.0, dot(d, d) - a * a);
    return std::sqrt(perp2 + a * a * shrink * shrink);
  }
};

//! Refuses a thickness beyond kFractureMaxThicknessRatio times the mesh's diagonal (of the picking
//! tree's box).
void check_thickness(double diagonal, double thickness) {
  if (thickness <= 0) return;
  if (thickness > kFractureMaxThicknessRatio * diagonal)
    throw InvalidInputError("fracture: thickness is " + number(thickness) + ", more than " +
                            number(kFractureMaxThicknessRatio) +
                            " times the diagonal of the mesh's bounding box (" + number(diagonal) +
                            "), the limit (kFractureMaxThicknessRatio); use a thickness of at most " +
                            number(kFractureMaxThicknessRatio * diagonal));
}

//! A face of the broken area.
struct AreaFace {
  Face face;
  double distance = 0;  // from the impact in the metric (see Area)
  Vec3d centroid;
};

//! The faces of the broken area: grown from the faces around `centre` over face adjacency, each
//! face keyed by the largest metric distance from p of the face centroids on its path (a path
//! that leaves the radius ends there). On a plate the key is the distance itself; on a curved or
//! folded surface the growth follows the surface and never jumps a gap. Faces in the order they
//! were settled (by key, then index).
class Area {
 public:
  std::vector<AreaFace> faces;
  //! face index -> position in `faces` (looked up only, never iterated).
  std::unordered_map<Index, std::uint32_t> slot;

  void gather(const SurfaceMesh& m, Vertex centre, const Vec3d& p, double radius, const Metric& metric) {
    faces.clear();
    slot.clear();
    using Item = std::pair<double, Index>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
    std::unordered_map<Index, double> best;
    auto offer = [&](Face g, double key) {
      auto [it, inserted] = best.emplace(g.idx(), key);
      if (!inserted) {
        if (key >= it->second) return;
        it->second = key;
      }
      heap.emplace(key, g.idx());
    };
    // A face with a corner that is not finite (a NaN written after the mesh was built, without the
    // change log's notice) never joins the area: it stays in the mesh as it was, and no shard takes
    // it. Checking here costs O(area), where a scan of every position would cost O(V) a strike.
    for (Face f : m.faces(centre))
      if (const Vec3d c = centroid(m, f); is_finite(c)) offer(f, metric.length(c - p));
    while (!heap.empty()) {
      const auto [d, fi] = heap.top();
      heap.pop();
      if (slot.count(fi) || d > best[fi]) continue;
      const Face f(fi);
      slot.emplace(fi, static_cast<std::uint32_t>(faces.size()));
      faces.push_back({f, d, centroid(m, f)});
      for (Face g : m.faces(f)) {
        if (slot.count(g.idx())) continue;
        const Vec3d cg = centroid(m, g);
        if (!is_finite(cg)) continue;
        const double dg = std::max(d, metric.length(cg - p));
        if (dg <= radius) offer(g, dg);
      }
    }
  }
};

//! Splits polygons of the area at their centroid and edges longer than max_edge at their midpoint
//! (longest first), for faces whose centroid lies within `radius` of p in the metric.
//! \return true if anything was split.
//! `budget`: the splits left for the strike, counted down.
bool refine(SurfaceMesh& m, const Area& area, const Vec3d& p, double radius, double max_edge,
            const Metric& metric, std::size_t& budget) {
  std::vector<Face> work;
  work.reserve(area.faces.size());
  for (const AreaFace& a : area.faces) work.push_back(a.face);
  bool changed = false;
  for (std::size_t i = 0; i < work.size() && budget > 0; ++i) {
    const Face f = work[i];
    if (!m.is_live(f)) continue;
    if (i >= area.faces.size() && metric.length(centroid(m, f) - p) > radius) continue;
    Vertex v;
    if (m.valence(f) > 3) {
      v = split_face(m, f, to_float(centroid(m, f)));
    } else {
      Halfedge longest;
      double best = max_edge;
      for (Halfedge h : m.halfedges(f)) {
        const double l = edge_length(m, h);
        if (l > best) {
          best = l;
          longest = h;
        }
      }
      if (!longest.is_valid()) continue;
      const Vec3d mid =
          (to_double(m.position(m.to_vertex(longest))) + to_double(m.position(m.from_vertex(longest)))) * 0.5;
      v = split_edge(m, SurfaceMesh::edge(longest), to_float(mid));
    }
    if (!v.is_valid()) continue;
    --budget;
    changed = true;
    for (Face g : m.faces(v)) work.push_back(g);
  }
  return changed;
}

//! Puts the impact into the mesh as a vertex, without making a sliver face.
Vertex cut_impact(SurfaceMesh& m, const LocateResult& hit, Vec3& point) {
  const auto& w = hit.barycentric;
  const std::size_t hi = static_cast<std::size_t>(std::max_element(w.begin(), w.end()) - w.begin());
  if (w[hi] >= 1 - kSnap) {
    point = m.position(hit.corners[hi]);
    return hit.corners[hi];
  }
  const std::size_t lo = static_cast<std::size_t>(std::min_element(w.begin(), w.end()) - w.begin());
  if (m.valence(hit.face) == 3 && w[lo] < kSnap) {
    const Vertex a = hit.corners[(lo + 1) % 3], b = hit.corners[(lo + 2) % 3];
    const double wa = w[(lo + 1) % 3], wb = w[(lo + 2) % 3];
    const Vec3d q = (to_double(m.position(a)) * wa + to_double(m.position(b)) * wb) * (1.0 / (wa + wb));
    point = to_float(q);
    const Vertex v = split_edge(m, m.find_edge(a, b), point);
    if (v.is_valid()) return v;
  }
  point = hit.point;
  return split_face(m, hit.face, point);
}

Vec3d any_perpendicular(const Vec3d& n) {
  const Vec3d axis = std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z) ? Vec3d{1, 0, 0}
                     : std::abs(n.y) <= std::abs(n.z)                                 ? Vec3d{0, 1, 0}
                                                                                      : Vec3d{0, 0, 1};
  return normalize(cross(n, axis));
}

//! What makes each shard a solid: its thickness in model units (0: none) and the "f:submesh" of
//! the faces the solid adds, both resolved for this strike; and the thickness of the shell an
//! open shard's mass properties are taken for (model units, positive).
struct Solid {
  double thickness = 0;
  std::int32_t inner_submesh = 1;
  double shell = 1;
};

//! The solid of an open shard: front, back copy `thickness` behind along the vertex normals
//! (reversed), and two triangles per boundary edge; the back and the walls get "f:submesh" =
//! inner_submesh. See Shard::mesh.
SurfaceMesh extrude(const SurfaceMesh& s, double thickness, std::int32_t inner_submesh) {
  const std::size_t n = s.vertex_slots();
  std::vector<Vec3d> normal(n);
  Vec3d total{};
  for (Face f : s.faces()) {
    const Vec3d a = area_vector(s, f);
    total += a;
    for (Vertex v : s.vertices(f)) normal[v.idx()] += a;
  }
  total = normalize(total);
  IndexedMesh im;
  im.positions.resize(2 * n);
  for (Vertex v : s.vertices()) {
    Vec3d nv = normalize(normal[v.idx()]);
    if (dot(nv, nv) == 0) nv = total;
    im.positions[v.idx()] = s.position(v);
    im.positions[n + v.idx()] = to_float(to_double(s.position(v)) - nv * thickness);
  }
  // Where each corner's properties come from: a half-edge of s (pointing to the front vertex).
  std::vector<Halfedge> corner_src;
  std::vector<Face> face_src;
  for (Face f : s.faces()) {
    std::size_t k = 0;
    for (Halfedge h : s.halfedges(f)) {
      im.indices.push_back(s.to_vertex(h).idx());
      corner_src.push_back(h);
      ++k;
    }
    im.face_sizes.push_back(static_cast<std::uint32_t>(k));
    face_src.push_back(f);
  }
  for (Face f : s.faces()) {
    std::vector<Halfedge> hs;
    for (Halfedge h : s.halfedges(f)) hs.push_back(h);
    for (auto it = hs.rbegin(); it != hs.rend(); ++it) {
      im.indices.push_back(static_cast<std::uint32_t>(n + s.to_vertex(*it).idx()));
      corner_src.push_back(*it);
    }
    im.face_sizes.push_back(static_cast<std::uint32_t>(hs.size()));
    face_src.push_back(f);
  }
  for (Halfedge h : s.halfedges()) {
    if (!s.is_boundary(h)) continue;
    const Index a = s.from_vertex(h).idx(), b = s.to_vertex(h).idx();
    const Halfedge at_a = SurfaceMesh::twin(h);  // in the front face, pointing to a
    const Halfedge at_b = s.prev(at_a);          // in the same face, pointing to b
    const Face f = s.face(at_a);
    im.indices.insert(im.indices.end(), {a, b, static_cast<std::uint32_t>(n + b)});
    corner_src.insert(corner_src.end(), {at_a, at_b, at_b});
    im.indices.insert(im.indices.end(),
                      {a, static_cast<std::uint32_t>(n + b), static_cast<std::uint32_t>(n + a)});
    corner_src.insert(corner_src.end(), {at_a, at_b, at_a});
    im.face_sizes.insert(im.face_sizes.end(), {3, 3});
    face_src.insert(face_src.end(), {f, f});
  }
  BuildOptions bo;
  bo.corner_attributes = false;
  BuildReport rep;
  SurfaceMesh out = build(im, bo, &rep);
  out.vertex_properties().add_missing_from(s.vertex_properties());
  out.halfedge_properties().add_missing_from(s.halfedge_properties());
  out.face_properties().add_missing_from(s.face_properties());
  for (Vertex v : out.vertices()) {
    const Index src = rep.vertex_origin[v.idx()];
    out.vertex_properties().copy_element_from(s.vertex_properties(), src % n, v.idx());
    out.position(v) = im.positions[src];
  }
  // The faces after the front ones (the back and the walls) are new cut faces: an inner submesh.
  // check_submesh() made sure an "f:submesh" of the mesh is of this type.
  FaceProperty<std::int32_t> submesh = out.face_property<std::int32_t>(kSubmeshProperty, 0);
  const std::size_t front = s.n_faces();
  std::size_t c = 0;
  for (std::size_t i = 0; i < face_src.size(); ++i) {
    const Face nf(rep.face_map[i]);
    out.face_properties().copy_element_from(s.face_properties(), face_src[i].idx(), nf.idx());
    if (i >= front) submesh[nf] = inner_submesh;
    for (Halfedge h : out.halfedges(nf))
      out.halfedge_properties().copy_element_from(s.halfedge_properties(), corner_src[c++].idx(), h.idx());
  }
  return out;
}

//! How far the farthest point lies beyond a face plane of the hull (0 for an empty hull).
double farthest_outside(const ConvexHull& hull, const std::vector<Vec3>& points) {
  double worst = 0;
  const SurfaceMesh& h = hull.mesh;
  for (Face f : h.faces()) {
    const Vec3d n = normalize(area_vector(h, f));
    const Vec3d a = to_double(h.position(h.to_vertex(h.halfedge(f))));
    for (const Vec3& q : points) worst = std::max(worst, dot(to_double(q) - a, n));
  }
  return worst;
}

void measure_shard(Shard& shard, const FractureOptions& o, const Solid& solid) {
  const SurfaceMesh& s = shard.mesh;
  double area = 0;
  Vec3d weighted{};
  for (Face f : s.faces()) {
    const double a = face_area(s, f);
    area += a;
    weighted += centroid(s, f) * a;
  }
  shard.area = area;
  shard.centroid = area > 0 ? weighted * (1.0 / area) : Vec3d{};
  bool boundary = false;
  for (Halfedge h : s.halfedges())
    if (s.is_boundary(h)) {
      boundary = true;
      break;
    }
  if (boundary && solid.thickness > 0) {
    shard.mesh = extrude(s, solid.thickness, solid.inner_submesh);
    boundary = false;
  }
  shard.closed = !boundary;
  try {
    if (shard.closed) {
      shard.mass = mass_properties(shard.mesh, o.density);
    } else {
      shard.shell_thickness = solid.shell;
      shard.mass = shell_mass_properties(shard.mesh, o.density, solid.shell);
    }
  } catch (const InvalidInputError&) {
    // Not a positive volume (folded by a thickness too large) or no area: nothing to weigh.
    shard.mass = MassProperties{};
  }
  if (o.hulls) {
    std::vector<Vec3> points;
    points.reserve(shard.mesh.n_vertices());
    for (Vertex v : shard.mesh.vertices()) points.push_back(shard.mesh.position(v));
    shard.hull = convex_hull(points, o.hull_options);
    // A safeguard on quickhull's rounding: every vertex is checked against the hull (O(points x
    // hull faces), small for a shard), and any that sticks out beyond the tolerance is reported.
    const double beyond = farthest_outside(shard.hull, points) - shard.hull.tolerance;
    shard.hull.max_outside_distance = std::max(shard.hull.max_outside_distance, beyond);
  }
}

// ---- the steps of fracture(), in order ----

//! Refuses an impact that is not finite, a mesh without faces, a FaceBvh of another mesh and a
//! thickness out of proportion (options are checked by fracture_break_points()).
void check_input(const SurfaceMesh& mesh, const Vec3& impact, const FractureOptions& o, const FaceBvh* bvh) {
  if (!is_finite(impact))
    throw InvalidInputError("fracture: the impact (" + number(impact.x) + ", " + number(impact.y) + ", " +
                            number(impact.z) + ") is not finite");
  if (mesh.n_faces() == 0) throw InvalidInputError("fracture: the mesh has no face");
  if (bvh && bvh->mesh() != &mesh)
    throw InvalidInputError("fracture: the FaceBvh was built over another mesh");
  if ((o.thickness > 0 || o.relative_thickness > 0) && mesh.face_properties().find_base(kSubmeshProperty) &&
      !mesh.get_face_property<std::int32_t>(kSubmeshProperty))
    throw InvalidInputError(std::string("fracture: the face property \"") + kSubmeshProperty +
                            "\" is not of type std::int32_t, so the shards' inner faces cannot be given "
                            "their submesh");
}

//! The "f:submesh" of the faces a solid adds: options.inner_submesh, or for -1 one more than the
//! largest of the mesh's live faces (1 when the mesh has no such property). O(F) for -1 with the
//! property, else O(1).
std::int32_t inner_submesh(const SurfaceMesh& mesh, const FractureOptions& o) {
  if (o.inner_submesh >= 0) return o.inner_submesh;
  const FaceProperty<std::int32_t> submesh = mesh.get_face_property<std::int32_t>(kSubmeshProperty);
  if (!submesh) return 1;
  std::int32_t largest = 0;
  for (Face f : mesh.faces()) largest = std::max(largest, submesh[f]);
  if (largest == std::numeric_limits<std::int32_t>::max())
    throw InvalidInputError(
        "fracture: the mesh's largest \"f:submesh\" is the largest int32; give "
        "inner_submesh explicitly");
  return largest + 1;
}

//! The nearest point of the surface to the impact, by bvh (brought up to date) or a tree of its
//! own, and the diagonal of that tree's box. Refuses an impact beyond the tolerance and a face
//! without a neighbour.
LocateResult locate_impact(SurfaceMesh& mesh, const Vec3& impact, const FractureOptions& o, FaceBvh* bvh,
                           double& diagonal) {
  std::optional<FaceBvh> own;
  FaceBvh* tree = bvh;
  if (tree) {
    tree->update();
  } else {
    own.emplace(mesh);
    tree = &*own;
  }
  diagonal = norm(to_double(tree->bounds().size()));
  const std::optional<LocateResult> hit = tree->closest_point(impact);
  if (!hit) throw InvalidInputError("fracture: no face found near the impact");
  const double tolerance = o.tolerance > 0 ? o.tolerance : 1e-3 * longest_edge(mesh, hit->face);
  const double distance = std::sqrt(hit->squared_distance);
  if (!(distance <= tolerance))
    throw InvalidInputError("fracture: the impact (" + number(impact.x) + ", " + number(impact.y) + ", " +
                            number(impact.z) + ") is " + number(distance) + " from the nearest face (" +
                            std::to_string(hit->face.idx()) + "), beyond the tolerance " + number(tolerance) +
                            "; the nearest point of the surface is (" + number(hit->point.x) + ", " +
                            number(hit->point.y) + ", " + number(hit->point.z) + ")");
  bool neighbour = false;
  for (Halfedge h : mesh.halfedges(hit->face))
    if (!mesh.is_boundary(SurfaceMesh::twin(h))) {
      neighbour = true;
      break;
    }
  if (!neighbour)
    throw InvalidInputError("fracture: face " + std::to_string(hit->face.idx()) +
                            " at the impact has no neighbour: too small to break");
  return *hit;
}

//! The frame of the impact: the face normal, two directions in its plane (t1 along the grain if
//! there is one), the metric, the model length of one unit of the rings' spacings, the break
//! radius and the radius of the broken area (half the outer spacing farther), both model units.
struct Frame {
  Vec3d normal, t1, t2;
  Metric metric;
  double unit = 1, break_radius = 0, radius = 0;
};

//! \throw InvalidInputError for a break radius that is not positive in model units (a mesh of
//!   zero extent).
Frame impact_frame(const SurfaceMesh& mesh, const LocateResult& hit, const FractureMaterial& mat,
                   double diagonal) {
  Frame f;
  const double scale = mat.units == FractureUnits::model          ? 1.0
                       : mat.units == FractureUnits::edge_lengths ? mean_edge_length(mesh, hit.face)
                                                                  : diagonal;
  f.break_radius = mat.radius * scale;
  if (!(f.break_radius > 0) || !std::isfinite(f.break_radius))
    throw InvalidInputError("fracture: the break radius is " + number(f.break_radius) +
                            " model units (radius " + number(mat.radius) + " in " +
                            fracture_units_name(mat.units) + " of " + number(scale) +
                            "), not a positive one");
  f.unit = f.break_radius / fracture_material_radius(mat);
  f.normal = normalize(area_vector(mesh, hit.face));
  if (dot(f.normal, f.normal) == 0) f.normal = {0, 0, 1};
  f.t1 = any_perpendicular(f.normal);
  if (mat.grain_stretch > 1) {
    const Vec3d g = normalize(to_double(mat.grain));
    const Vec3d in_plane = g - f.normal * dot(g, f.normal);
    if (norm(in_plane) > std::sin(6 * std::numbers::pi / 180)) {
      f.t1 = normalize(in_plane);
      f.metric.axis = f.t1;
      f.metric.shrink = 1 / mat.grain_stretch;
    }
  }
  f.t2 = cross(f.normal, f.t1);
  f.radius = f.break_radius + 0.5 * mat.rings.back().spacing * f.unit;
  return f;
}

//! The broken area about the impact p (at vertex centre), refined where its faces are large. The
//! time goes to result.seconds (gathering as scatter, splitting as cut).
Area broken_area(SurfaceMesh& mesh, Vertex centre, const Vec3d& p, const Frame& frame,
                 const FractureMaterial& mat, FractureResult& result, Clock::time_point& t) {
  Area area;
  area.gather(mesh, centre, p, frame.radius, frame.metric);
  result.seconds.scatter += seconds_since(t);
  std::size_t budget = kFractureMaxRefineSplits;
  // Splits change the centroids and so the area's rim: again until nothing is split (a polygon or a
  // long edge newly reached at the rim), a few rounds at most.
  for (int round = 0;
       round < 8 && refine(mesh, area, p, frame.radius, mat.refine_edge * frame.unit, frame.metric, budget);
       ++round) {
    result.seconds.cut += seconds_since(t);
    area.gather(mesh, centre, p, frame.radius, frame.metric);
    result.seconds.scatter += seconds_since(t);
  }
  return area;
}

//! The break points of the rings, drawn in the impact's plane and carried onto the surface: each
//! goes to the area face whose centroid, mapped to polar form about p, is nearest. Returns the
//! area slots of the distinct faces hit, in the order first hit.
std::vector<std::uint32_t> scatter(const Area& area, const Vec3d& p, const Frame& frame,
                                   const FractureMaterial& mat, std::uint64_t seed) {
  const std::size_t k = area.faces.size();
  std::vector<std::array<double, 2>> polar(k);
  for (std::size_t i = 0; i < k; ++i) {
    const Vec3d d = area.faces[i].centroid - p;
    const double x = dot(d, frame.t1) * frame.metric.shrink, y = dot(d, frame.t2);
    const double len = std::hypot(x, y);
    const double r = area.faces[i].distance;
    polar[i] = len > 0 ? std::array<double, 2>{r * x / len, r * y / len} : std::array<double, 2>{0, 0};
  }
  SplitMix64 rng(seed);
  std::vector<std::uint32_t> seeds;
  std::vector<std::int32_t> seed_of(k, -1);
  double ring_radius = 0;
  for (const FractureRing& ring : mat.rings) {
    ring_radius += ring.spacing;
    const double phase = 2 * std::numbers::pi * rng.uniform();
    for (unsigned i = 0; i < ring.points; ++i) {
      const double angle =
          phase + 2 * std::numbers::pi * (i + ring.jitter * (rng.uniform() - 0.5)) / ring.points;
      const double r = (ring_radius + ring.jitter * ring.spacing * (rng.uniform() - 0.5)) * frame.unit;
      const double x = r * std::cos(angle), y = r * std::sin(angle);
      std::size_t best = 0;
      double best_d = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < k; ++j) {
        const double dx = polar[j][0] - x, dy = polar[j][1] - y;
        const double d = dx * dx + dy * dy;
        if (d < best_d) {
          best_d = d;
          best = j;
        }
      }
      if (seed_of[best] < 0) {
        seed_of[best] = static_cast<std::int32_t>(seeds.size());
        seeds.push_back(static_cast<std::uint32_t>(best));
      }
    }
  }
  return seeds;
}

//! The cells: each face of the area goes to its nearest break point along the surface (a
//! Dijkstra over face adjacency from all seeds at once). One list of faces per seed.
std::vector<std::vector<Face>> cells(const SurfaceMesh& mesh, const Area& area,
                                     const std::vector<std::uint32_t>& seeds, const Metric& metric) {
  const std::size_t k = area.faces.size();
  std::vector<std::int32_t> cell(k, -1);
  using Item = std::tuple<double, std::int32_t, std::uint32_t>;  // distance, cell, area slot
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  std::vector<double> best(k, std::numeric_limits<double>::infinity());
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    best[seeds[s]] = 0;
    heap.emplace(0.0, static_cast<std::int32_t>(s), seeds[s]);
  }
  while (!heap.empty()) {
    const auto [d, c, i] = heap.top();
    heap.pop();
    if (cell[i] >= 0) continue;
    cell[i] = c;
    for (Face g : mesh.faces(area.faces[i].face)) {
      const auto it = area.slot.find(g.idx());
      if (it == area.slot.end() || cell[it->second] >= 0) continue;
      const double dg =
          std::max(d, metric.length(area.faces[it->second].centroid - area.faces[seeds[c]].centroid));
      if (dg < best[it->second]) {
        best[it->second] = dg;
        heap.emplace(dg, c, it->second);
      }
    }
  }
  std::vector<std::vector<Face>> faces(seeds.size());
  for (std::size_t i = 0; i < k; ++i)
    if (cell[i] >= 0) faces[static_cast<std::size_t>(cell[i])].push_back(area.faces[i].face);
  return faces;
}

//! Each non-empty cell detached from the mesh into a shard of its own (faces in index order).
std::vector<Shard> detach(SurfaceMesh& mesh, std::vector<std::vector<Face>>& cells) {
  std::vector<Shard> shards;
  shards.reserve(cells.size());
  for (std::vector<Face>& faces : cells) {
    if (faces.empty()) continue;
    std::sort(faces.begin(), faces.end());
    Shard shard;
    shard.mesh = detach_faces(mesh, faces);
    shards.push_back(std::move(shard));
  }
  return shards;
}

//! The diagonal of the box of every shard's vertices: the size of what broke off. O(k).
double span(const std::vector<Shard>& shards) {
  BoundingBox all;
  for (const Shard& shard : shards) {
    const BoundingBox box = bounding_box(shard.mesh);
    if (box.empty) continue;
    for (int a = 0; a < 3; ++a) {
      all.min[a] = all.empty ? box.min[a] : std::min(all.min[a], box.min[a]);
      all.max[a] = all.empty ? box.max[a] : std::max(all.max[a], box.max[a]);
    }
    all.empty = false;
  }
  return norm(to_double(all.size()));
}

//! Every shard made a solid and measured (measure_shard).
void solids(std::vector<Shard>& shards, const FractureOptions& o, const Solid& solid) {
  for (Shard& shard : shards) measure_shard(shard, o, solid);
}

}  // namespace

// The pipeline: locate the impact, take its frame, cut it into the surface, gather the broken area
// (refined where its faces are large), scatter the break points, grow a cell about each, detach
// the cells and make each a solid. Each step is a function of its own above.
FractureResult fracture(SurfaceMesh& mesh, const Vec3& impact, const FractureOptions& o, FaceBvh* bvh) {
  const std::size_t total_points = fracture_break_points(o);  // checks the options
  check_input(mesh, impact, o, bvh);
  FractureResult result;
  Clock::time_point t = Clock::now();

  double diagonal = 0;
  const LocateResult hit = locate_impact(mesh, impact, o, bvh, diagonal);
  result.impact_face = hit.face;
  result.impact_point = hit.point;
  check_thickness(diagonal, o.thickness);
  result.seconds.locate = seconds_since(t);
  if (total_points == 0) return result;

  const Frame frame = impact_frame(mesh, hit, o.material, diagonal);
  result.break_radius = frame.break_radius;
  // The solid's thickness in model units (a relative one is known only now, from the break radius;
  // fracture_break_points() bounded it), the inner faces' submesh and the shell's thickness, all settled
  // before the mesh is edited.
  Solid solid;
  if (o.thickness > 0 || o.relative_thickness > 0) {
    solid.thickness = o.thickness > 0 ? o.thickness : o.relative_thickness * frame.break_radius;
    solid.inner_submesh = inner_submesh(mesh, o);
  }
  solid.shell = o.shell_thickness > 0 ? o.shell_thickness : kFractureDefaultShellRatio * frame.break_radius;
  Vec3 impact_on_surface;
  const Vertex centre = cut_impact(mesh, hit, impact_on_surface);
  result.impact_point = impact_on_surface;
  const Vec3d p = to_double(impact_on_surface);
  result.seconds.cut += seconds_since(t);

  const Area area = broken_area(mesh, centre, p, frame, o.material, result, t);
  const std::vector<std::uint32_t> seeds = scatter(area, p, frame, o.material, o.seed);
  result.seconds.scatter += seconds_since(t);

  std::vector<std::vector<Face>> faces_of_cell = cells(mesh, area, seeds, frame.metric);
  result.seconds.cut += seconds_since(t);

  result.shards = detach(mesh, faces_of_cell);
  if (bvh) bvh->update();
  result.seconds.detach += seconds_since(t);

  if (o.relative_thickness > 0 || o.shell_thickness == 0) {
    const double size = span(result.shards);
    if (o.relative_thickness > 0) solid.thickness = std::min(solid.thickness, o.relative_thickness * size);
    if (o.shell_thickness == 0 && size > 0)
      solid.shell = std::min(solid.shell, kFractureDefaultShellRatio * size);
  }
  solids(result.shards, o, solid);
  result.seconds.hulls += seconds_since(t);
  return result;
}

}  // namespace hedge
