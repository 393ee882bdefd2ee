// Decimation's checks outside the collapse loop (decimate_checks.h).
#include "decimate_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/locate.h"
#include "hedge/error.h"
#include "locate_internal.h"

namespace hedge::detail::decimation {

namespace {

std::string vertex_name(Vertex v) { return "vertex " + std::to_string(v.idx()); }

}  // namespace

void check_input(const SurfaceMesh& m, const DecimateOptions& o) {
  auto non_negative = [](double x, const char* name) {
    if (!(x >= 0) || !std::isfinite(x))
      throw InvalidInputError(std::string("decimate: ") + name + " must be finite and not negative, got " +
                              std::to_string(x));
  };
  if (!(o.max_error >= 0))
    throw InvalidInputError("decimate: max_error must not be negative or NaN, got " +
                            std::to_string(o.max_error));
  non_negative(o.boundary_weight, "boundary_weight");
  non_negative(o.feature_weight, "feature_weight");
  non_negative(o.feature_angle_degrees, "feature_angle_degrees");
  non_negative(o.attribute_weight, "attribute_weight");
  if (!(o.max_normal_change_degrees > 0 && o.max_normal_change_degrees <= 180))
    throw InvalidInputError("decimate: max_normal_change_degrees must be in (0, 180], got " +
                            std::to_string(o.max_normal_change_degrees));
  for (Face f : m.faces())
    if (m.valence(f) != 3)
      throw InvalidInputError("decimate: face " + std::to_string(f.idx()) + " has " +
                              std::to_string(m.valence(f)) +
                              " corners; decimation needs triangles (triangulate first)");
  require_finite_positions(m, "decimate");
  for (Vertex v : m.vertices()) {
    if (!m.is_manifold(v))
      throw InvalidInputError("decimate: " + vertex_name(v) +
                              " is not manifold (its faces form more than one fan)");
  }
}

double removed_distance2(const SurfaceMesh& m, Halfedge h, const Vec3d& p, double limit) {
  // The triangle code of point location, called in double on the float positions converted once
  // (closest_point_on_triangle() converts them per call, out of line): the same answers, bit for bit.
  using locate_detail::closest_on_triangle;
  const Face fl = m.face(h), fr = m.face(SurfaceMesh::twin(h));
  const Vec3 xb_f = m.position(m.to_vertex(h)), x_f = to_float(p);
  const Vec3d xa = to_double(m.position(m.from_vertex(h))), xb = to_double(xb_f), x = to_double(x_f);
  const bool moved = !(x_f == xb_f);
  double da = std::numeric_limits<double>::infinity(), db = moved ? da : 0.0;
  const bool can_stop = std::isfinite(limit);
  for (const Halfedge start : {h, SurfaceMesh::twin(h)}) {
    Halfedge o = start;
    do {
      const Face f = m.face(o);
      if (f.is_valid() && f != fl && f != fr) {
        const Vec3d b = to_double(m.position(m.to_vertex(o))),
                    c = to_double(m.position(m.to_vertex(m.next(o))));
        if (!can_stop || da > limit) da = std::min(da, closest_on_triangle(xa, x, b, c).squared_distance);
        if (!can_stop || db > limit) db = std::min(db, closest_on_triangle(xb, x, b, c).squared_distance);
        if (can_stop && da <= limit && db <= limit) return std::max(da, db);
      }
      o = m.rotate_cw(o);
    } while (o != start);
  }
  const double d = std::max(da, db);
  return std::isfinite(d) ? d : 0.0;
}

double bridge_distance2(const SurfaceMesh& m, Halfedge h, const Vec3d& p, double limit) {
  // As removed_distance2(): point location's triangle code in double, on float positions converted
  // once (the answers of closest_point_on_triangle(), bit for bit).
  using locate_detail::closest_on_triangle;
  const Vec3 x = to_float(p);
  // No limit: every distance exact.
  if (!std::isfinite(limit)) limit = -1;
  // The old faces around either end, in the order they are searched, gathered when first needed
  // into storage the thread keeps (nothing allocated or cleared per call once it has grown).
  struct Old {
    Vec3d a, b, c;
    Vec3d lo, hi;  // box
    bool far;
  };
  thread_local std::vector<Old> old;
  bool gathered = false;
  auto gather = [&] {
    gathered = true;
    old.clear();
    for (const Halfedge start : {h, SurfaceMesh::twin(h)}) {
      Halfedge o = start;
      do {
        if (m.face(o).is_valid()) {
          Old& t = old.emplace_back();
          t.a = to_double(m.position(m.from_vertex(o)));
          t.b = to_double(m.position(m.to_vertex(o)));
          t.c = to_double(m.position(m.to_vertex(m.next(o))));
          for (int k = 0; k < 3; ++k) {
            t.lo[k] = std::min({t.a[k], t.b[k], t.c[k]});
            t.hi[k] = std::max({t.a[k], t.b[k], t.c[k]});
          }
        }
        o = m.rotate_cw(o);
      } while (o != start);
    }
  };
  // The squared distance of g to the nearest old face around either end, or some value at most
  // `limit` once one is that near. A face whose box is farther than the limit cannot be within it:
  // its exact distance is needed only if no face is (then the nearest's, over all of them, which
  // is what a walk of every face would give).
  auto nearest_old = [&](const Vec3& g) {
    if (!gathered) gather();
    const Vec3d dg = to_double(g);
    double best = std::numeric_limits<double>::infinity();
    for (Old& t : old) {
      double box2 = 0;
      for (int k = 0; k < 3; ++k) {
        const double out = std::max({t.lo[k] - dg[k], dg[k] - t.hi[k], 0.0});
        box2 += out * out;
      }
      t.far = box2 > limit;
      if (t.far) continue;
      best = std::min(best, closest_on_triangle(dg, t.a, t.b, t.c).squared_distance);
      if (best <= limit) return best;
    }
    for (const Old& t : old)
      if (t.far) best = std::min(best, closest_on_triangle(dg, t.a, t.b, t.c).squared_distance);
    return best;
  };
  const Face fl = m.face(h), fr = m.face(SurfaceMesh::twin(h));
  double worst = 0;
  for (const Halfedge start : {h, SurfaceMesh::twin(h)}) {
    // Each new face (x, b, c) of this end replaces (y, b, c), y the end's old position; their
    // centroids are |x - y| / 3 apart, which bounds the distance to the old face for all of them.
    const Vec3 y = m.position(m.from_vertex(start));
    const Vec3d xy = to_double(x) - to_double(y), dy = to_double(y);
    if (dot(xy, xy) <= 9 * limit) continue;
    Halfedge o = start;
    do {
      const Face f = m.face(o);
      if (f.is_valid() && f != fl && f != fr) {
        const Vec3 b = m.position(m.to_vertex(o)), c = m.position(m.to_vertex(m.next(o)));
        const Vec3 g{(x.x + b.x + c.x) / 3, (x.y + b.y + c.y) / 3, (x.z + b.z + c.z) / 3};
        // The face it replaces is nearly always the nearest: try it first.
        double d = closest_on_triangle(to_double(g), dy, to_double(b), to_double(c)).squared_distance;
        if (d > limit) d = std::min(d, nearest_old(g));
        worst = std::max(worst, d);
      }
      o = m.rotate_cw(o);
    } while (o != start);
  }
  return worst;
}

}  // namespace hedge::detail::decimation
