// Solid fracture: positions of keyed points, triangles clipped by half-spaces, and planar regions
// (caps, and the parts of triangles outside the broken region) traced and triangulated.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>

#include "fracture_solid_internal.h"

namespace hedge::solid_detail {

Vec3d Geometry::vertex(Index v) const { return to_double(mesh->position(Vertex(v))); }

// Each position is computed from its key alone, in a fixed order of its inputs (a point where a
// triangle meets two planes is placed by clip_triangle(), the one place it is made).
Vec3d Geometry::position(const Key& k) const {
  switch (k.kind) {
    case Key::vertex:
      return vertex(k.a);
    case Key::edge: {
      const Vec3d pa = vertex(k.a), pb = vertex(k.b);
      const Plane& p = planes->planes[k.c];
      const double sa = p.value(pa), sb = p.value(pb);
      const double t = sa == sb ? 0.5 : std::clamp(sa / (sa - sb), 0.0, 1.0);
      return pa + (pb - pa) * t;
    }
    default:
      return corners->at(k);
  }
}

// Sutherland-Hodgman, one half-space after the other. A point made on an edge of the triangle's
// own sides is (edge, plane); on a line of an earlier plane p it is (triangle, p, plane).
void clip_triangle(const Geometry& g, std::uint32_t t, const std::vector<HalfSpace>& planes, ClipPolygon& out,
                   std::size_t first) {
  const SoupTriangle& tri = (*g.soup)[t];
  out.triangle = t;
  out.keys.clear();
  out.pos.clear();
  out.support.clear();
  for (int k = 0; k < 3; ++k) {
    out.keys.push_back({Key::vertex, tri.v[k], 0, 0});
    out.pos.push_back(g.vertex(tri.v[k]));
    out.support.push_back(kNoPlane);
  }
  // Scratch kept between calls: a strike clips tens of thousands of triangles.
  thread_local std::vector<Key> keys;
  thread_local std::vector<Vec3d> pos;
  thread_local std::vector<std::uint32_t> support;
  thread_local std::vector<char> in;
  for (std::size_t hi = first; hi < planes.size(); ++hi) {
    const HalfSpace& h = planes[hi];
    const Plane& pl = g.planes->planes[h.plane];
    const std::size_t n = out.keys.size();
    in.resize(n);
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i) count += (in[i] = char(pl.below(out.pos[i]) != h.flip));
    if (count == n) continue;
    if (count == 0) {
      out.keys.clear();
      return;
    }
    keys.clear();
    pos.clear();
    support.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      if (in[i]) {
        keys.push_back(out.keys[i]);
        pos.push_back(out.pos[i]);
        support.push_back(out.support[i]);
      }
      if (in[i] != in[j]) {
        Key x;
        if (out.support[i] == kNoPlane) {
          // On the triangle's side from corner m to m+1: name it by its mesh vertices.
          const Key& a = out.keys[i];
          const Key& b = out.keys[j];
          // Both ends lie on that side; a vertex key names a corner, an edge key its corners.
          Index u, w;
          if (a.kind == Key::vertex && b.kind == Key::vertex) {
            u = a.a;
            w = b.a;
          } else {
            const Key& e = a.kind == Key::edge ? a : b;
            u = e.a;
            w = e.b;
          }
          x = {Key::edge, std::min(u, w), std::max(u, w), h.plane};
        } else {
          const std::uint32_t p = out.support[i];
          x = {Key::triangle, t, std::min(p, h.plane), std::max(p, h.plane)};
        }
        keys.push_back(x);
        if (x.kind == Key::edge) {
          pos.push_back(g.position(x));
        } else {
          // Along the edge of plane p inside the triangle: well conditioned even where the line of
          // p and the plane grazes the triangle (where the meeting of three planes is not). The
          // key occurs in this polygon only, so this is its one position.
          const Vec3d& pu = out.pos[i];
          const Vec3d& pw = out.pos[j];
          const double su = pl.value(pu), sw = pl.value(pw);
          const double t = su == sw ? 0.5 : std::clamp(su / (su - sw), 0.0, 1.0);
          pos.push_back(pu + (pw - pu) * t);
        }
        // in -> out: the edge from x on runs along the plane; out -> in: it is the rest of edge i.
        support.push_back(in[i] ? h.plane : out.support[i]);
      }
    }
    out.keys.swap(keys);
    out.pos.swap(pos);
    out.support.swap(support);
  }
}

namespace {

//! A perimeter point of the outline: a corner (role 0), or a chain end: where a chain starts
//! (role 1, the outline arrives there) or ends (role 2, the outline leaves from there).
struct Stop {
  Key key;
  Vec3d pos;
  int role = 0;
};

//! A closed loop of a region's boundary, in the region's plane.
struct Loop {
  std::vector<std::uint32_t> ids;
  std::vector<std::array<double, 2>> xy;
  double area = 0;
};

//! fill_region()'s storage, kept from one call to the next on each thread: a strike fills
//! thousands of regions (every cap, and the part of every cut triangle outside the broken region),
//! and most are small. Each call clears what it uses first.
struct FillScratch {
  std::vector<std::pair<Key, Key>> edges;
  std::vector<std::pair<Key, Vec3d>> where, merged;
  std::vector<std::pair<Key, int>> role;
  std::vector<std::vector<Stop>> on_side;
  std::vector<Stop> outline;
  std::vector<char> used;
  std::vector<Loop> loops;  // the first `loop_count` are in use
  std::size_t loop_count = 0;
  std::vector<Key> names;
  std::vector<std::uint32_t> id_of;
  std::vector<std::size_t> outer, holes;
  std::vector<std::vector<std::size_t>> holes_of;
  std::vector<std::vector<std::array<double, 2>>> hxy;
  std::vector<std::vector<std::uint32_t>> hid;
  std::vector<std::array<std::uint32_t, 3>> ids;
};

}  // namespace

bool fill_region(const RegionInput& in, std::vector<std::array<Key, 3>>& tris,
                 std::vector<std::pair<Key, Vec3d>>& points) {
  const std::size_t n = in.corners.size();
  thread_local FillScratch scratch;
  // The graph of boundary edges: chains, then the outline's pieces inside the region.
  std::vector<std::pair<Key, Key>>& edges = scratch.edges;
  // Flat maps, sorted by key: a point's position (the first one given wins) and its role.
  std::vector<std::pair<Key, Vec3d>>& where = scratch.where;
  std::vector<std::pair<Key, int>>& role =
      scratch.role;  // 1: outgoing chain edge only, 2: incoming only, 3: both
  edges.clear();
  where.clear();
  role.clear();
  for (const ChainEdge& e : in.chain) {
    edges.emplace_back(e.a, e.b);
    where.emplace_back(e.a, e.pa);
    where.emplace_back(e.b, e.pb);
    role.emplace_back(e.a, 1);
    role.emplace_back(e.b, 2);
  }
  const auto by_key = [](const auto& x, const auto& y) { return x.first < y.first; };
  const auto same_key = [](const auto& x, const auto& y) { return x.first == y.first; };
  // Sorted by key, the first position given for a key kept.
  std::stable_sort(where.begin(), where.end(), by_key);
  where.erase(std::unique(where.begin(), where.end(), same_key), where.end());
  const auto slot = [&](const Key& k) {
    return static_cast<std::size_t>(
        std::lower_bound(where.begin(), where.end(), k,
                         [](const auto& x, const Key& key) { return x.first < key; }) -
        where.begin());
  };
  std::sort(role.begin(), role.end(), by_key);
  std::size_t roles = 0;
  for (std::size_t i = 0; i < role.size(); ++i)
    if (roles > 0 && role[roles - 1].first == role[i].first)
      role[roles - 1].second |= role[i].second;
    else
      role[roles++] = role[i];
  role.resize(roles);
  std::vector<std::vector<Stop>>& on_side = scratch.on_side;
  if (on_side.size() < n) on_side.resize(n);
  for (std::size_t s = 0; s < n; ++s) on_side[s].clear();
  for (const auto& [k, r] : role) {
    if (r == 3) continue;
    const int s = in.side(k);
    if (s < 0) return false;  // a chain end inside the outline, or on no side of it
    on_side[static_cast<std::size_t>(s)].push_back({k, where[slot(k)].second, r});
  }
  std::vector<Stop>& outline = scratch.outline;
  outline.clear();
  for (std::size_t s = 0; s < n; ++s) {
    outline.push_back({in.corners[s], in.corner_pos[s], 0});
    std::vector<Stop>& stops = on_side[s];
    // Ordered along the side from its corner of smaller key, ties by key, so the two regions that
    // share a side see its points in the same order; then in this side's direction.
    const std::size_t t = (s + 1) % n;
    const bool forward = in.corners[s] < in.corners[t];
    const Vec3d o = forward ? in.corner_pos[s] : in.corner_pos[t];
    const Vec3d d = forward ? in.corner_pos[t] - in.corner_pos[s] : in.corner_pos[s] - in.corner_pos[t];
    std::sort(stops.begin(), stops.end(), [&](const Stop& x, const Stop& y) {
      const double px = dot(x.pos - o, d), py = dot(y.pos - o, d);
      if (px != py) return px < py;
      return x.key < y.key;
    });
    if (!forward) std::reverse(stops.begin(), stops.end());
    outline.insert(outline.end(), stops.begin(), stops.end());
  }
  std::size_t first = outline.size();
  for (std::size_t i = 0; i < outline.size(); ++i)
    if (outline[i].role != 0) {
      first = i;
      break;
    }
  {
    // The outline's points join `where` (sorted, unique): sorted among themselves (stably: the
    // first given wins), then merged in, a key already there keeping its position.
    const std::size_t old = where.size();
    for (const Stop& s : outline) where.emplace_back(s.key, s.pos);
    const auto tail = where.begin() + static_cast<std::ptrdiff_t>(old);
    if (outline.size() > 64) {
      std::stable_sort(tail, where.end(), by_key);
    } else {
      for (auto it = tail + 1; it < where.end(); ++it)  // insertion sort: the outline is short
        for (auto at = it; at != tail && at->first < (at - 1)->first; --at) std::iter_swap(at, at - 1);
    }
    std::vector<std::pair<Key, Vec3d>>& merged = scratch.merged;
    merged.clear();
    auto a = where.begin();
    for (auto b = tail; b != where.end(); ++b) {
      if (b != tail && b->first == (b - 1)->first) continue;
      while (a != tail && a->first < b->first) merged.push_back(*a++);
      if (a == tail || b->first < a->first) merged.push_back(*b);
    }
    merged.insert(merged.end(), a, tail);
    where.swap(merged);
  }
  if (first == outline.size()) {
    if (in.inside())
      for (std::size_t i = 0; i < n; ++i) edges.emplace_back(in.corners[i], in.corners[(i + 1) % n]);
  } else {
    bool inside = outline[first].role == 2;
    const std::size_t m = outline.size();
    for (std::size_t step = 1; step <= m; ++step) {
      const Stop& prev = outline[(first + step - 1) % m];
      const Stop& cur = outline[(first + step) % m];
      if (inside) edges.emplace_back(prev.key, cur.key);
      if (cur.role == 1) {
        if (!inside) return false;  // the outline arrives at a chain's start from outside
        inside = false;
      } else if (cur.role == 2) {
        if (inside) return false;
        inside = true;
      }
    }
  }
  if (edges.empty()) return true;
  // Loops: every point has one edge out and one in.
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 1; i < edges.size(); ++i)
    if (edges[i].first == edges[i - 1].first) return false;
  std::vector<char>& used = scratch.used;
  used.assign(edges.size(), 0);
  Vec3d u, v;
  plane_frame(in.normal, u, v);
  std::vector<Loop>& loop_store = scratch.loops;
  std::size_t& loop_count = scratch.loop_count;
  loop_count = 0;
  std::vector<Key>& names = scratch.names;  // id -> key, in the order of first use
  names.clear();
  std::vector<std::uint32_t>& id_of = scratch.id_of;  // by slot in `where`
  id_of.assign(where.size(), kNoPlane);
  auto id = [&](std::size_t at) {
    if (id_of[at] == kNoPlane) {
      id_of[at] = static_cast<std::uint32_t>(names.size());
      names.push_back(where[at].first);
    }
    return id_of[at];
  };
  const Vec3d origin = in.corner_pos.empty() ? Vec3d{} : in.corner_pos[0];
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (used[i]) continue;
    if (loop_count == loop_store.size()) loop_store.emplace_back();
    Loop& loop = loop_store[loop_count];
    loop.ids.clear();
    loop.xy.clear();
    loop.area = 0;
    std::size_t e = i;
    while (!used[e]) {
      used[e] = 1;
      const Key& k = edges[e].first;
      const std::size_t at = slot(k);
      const Vec3d p = where[at].second - origin;
      loop.ids.push_back(id(at));
      loop.xy.push_back({dot(p, u), dot(p, v)});
      const auto it = std::lower_bound(edges.begin(), edges.end(), std::make_pair(edges[e].second, Key{}));
      if (it == edges.end() || it->first != edges[e].second) return false;  // an open chain
      e = static_cast<std::size_t>(it - edges.begin());
    }
    if (e != i) return false;
    for (std::size_t a = 0; a < loop.xy.size(); ++a) {
      const auto& p = loop.xy[a];
      const auto& q = loop.xy[(a + 1) % loop.xy.size()];
      loop.area += p[0] * q[1] - q[0] * p[1];
    }
    if (loop.ids.size() >= 3 || loop.area != 0)
      ++loop_count;
    else if (loop.ids.size() < 3)
      return false;
  }
  const std::span<const Loop> loops(loop_store.data(), loop_count);
  // Outer loops turn counter-clockwise; each hole goes to the smallest outer loop around it.
  auto contains = [](const Loop& l, const std::array<double, 2>& p) {
    bool odd = false;
    for (std::size_t a = 0, b = l.xy.size() - 1; a < l.xy.size(); b = a++) {
      const auto& pa = l.xy[a];
      const auto& pb = l.xy[b];
      if ((pa[1] > p[1]) != (pb[1] > p[1]) &&
          p[0] < (pb[0] - pa[0]) * (p[1] - pa[1]) / (pb[1] - pa[1]) + pa[0])
        odd = !odd;
    }
    return odd;
  };
  std::vector<std::size_t>& outer = scratch.outer;
  std::vector<std::size_t>& holes = scratch.holes;
  outer.clear();
  holes.clear();
  for (std::size_t i = 0; i < loops.size(); ++i) (loops[i].area >= 0 ? outer : holes).push_back(i);
  std::vector<std::vector<std::size_t>>& holes_of = scratch.holes_of;
  if (holes_of.size() < loops.size()) holes_of.resize(loops.size());
  for (std::size_t i = 0; i < loops.size(); ++i) holes_of[i].clear();
  for (std::size_t h : holes) {
    std::size_t best = loops.size();
    for (std::size_t o : outer) {
      // The hole's point farthest into the outer loop would be better; its first point will do
      // unless it touches the outer loop, so try every point until one is decided.
      bool in_o = false;
      for (const auto& p : loops[h].xy)
        if (contains(loops[o], p)) {
          in_o = true;
          break;
        }
      if (in_o && (best == loops.size() || loops[o].area < loops[best].area)) best = o;
    }
    if (best == loops.size()) return false;
    holes_of[best].push_back(h);
  }
  std::vector<std::array<std::uint32_t, 3>>& ids = scratch.ids;
  ids.clear();
  std::vector<std::vector<std::array<double, 2>>>& hxy = scratch.hxy;
  std::vector<std::vector<std::uint32_t>>& hid = scratch.hid;
  for (std::size_t o : outer) {
    hxy.resize(holes_of[o].size());
    hid.resize(holes_of[o].size());
    for (std::size_t k = 0; k < holes_of[o].size(); ++k) {
      hxy[k].assign(loops[holes_of[o][k]].xy.begin(), loops[holes_of[o][k]].xy.end());
      hid[k].assign(loops[holes_of[o][k]].ids.begin(), loops[holes_of[o][k]].ids.end());
    }
    if (!triangulate_with_holes(loops[o].xy, loops[o].ids, hxy, hid, ids)) return false;
  }
  for (const auto& t : ids) tris.push_back({names[t[0]], names[t[1]], names[t[2]]});
  for (std::size_t i = 0; i < names.size(); ++i) points.emplace_back(names[i], where[slot(names[i])].second);
  return true;
}

namespace {

using P2 = std::array<double, 2>;

double orient(const P2& a, const P2& b, const P2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

//! True if segments ab and cd cross at a point inside both (touching at an end does not count).
bool crosses(const P2& a, const P2& b, const P2& c, const P2& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

//! True if p lies on the open segment ab: exactly on its line, strictly between its ends.
bool on_segment(const P2& a, const P2& b, const P2& p) {
  if (orient(a, b, p) != 0) return false;
  const double t = (p[0] - a[0]) * (b[0] - a[0]) + (p[1] - a[1]) * (b[1] - a[1]);
  const double l = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
  return t > 0 && t < l;
}

}  // namespace

// Holes are bridged, rightmost first, from their rightmost point to the nearest point of the
// polygon built so far that sees it (the bridge crosses no edge of the polygon or of a hole left,
// and passes through none of their points: a bridge along a row of points, as a cut through a
// circle's leftmost and rightmost points makes, would cross the hole without crossing an edge);
// then ears are clipped, the convex corner with no other point inside first, and where none is
// left (rounding) the most convex corner of three distinct points.
bool triangulate_with_holes(const std::vector<P2>& outer_xy, const std::vector<std::uint32_t>& outer_id,
                            const std::vector<std::vector<P2>>& holes_xy,
                            const std::vector<std::vector<std::uint32_t>>& holes_id,
                            std::vector<std::array<std::uint32_t, 3>>& tris) {
  // Storage kept from one call to the next on each thread (most calls have no hole).
  thread_local std::vector<P2> xy;
  thread_local std::vector<std::uint32_t> id;
  thread_local std::vector<std::size_t> ring;
  xy.assign(outer_xy.begin(), outer_xy.end());
  id.assign(outer_id.begin(), outer_id.end());
  std::vector<std::size_t> order(holes_xy.size());
  std::vector<std::size_t> right(holes_xy.size());
  for (std::size_t h = 0; h < holes_xy.size(); ++h) {
    order[h] = h;
    std::size_t r = 0;
    for (std::size_t i = 1; i < holes_xy[h].size(); ++i)
      if (holes_xy[h][i][0] > holes_xy[h][r][0] ||
          (holes_xy[h][i][0] == holes_xy[h][r][0] && holes_id[h][i] < holes_id[h][r]))
        r = i;
    right[h] = r;
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const double xa = holes_xy[a][right[a]][0], xb = holes_xy[b][right[b]][0];
    return xa != xb ? xa > xb : a < b;
  });
  std::vector<char> done(holes_xy.size(), 0);
  for (std::size_t h : order) {
    const P2 m = holes_xy[h][right[h]];
    std::vector<std::pair<double, std::size_t>> cand;
    for (std::size_t i = 0; i < xy.size(); ++i) {
      const double dx = xy[i][0] - m[0], dy = xy[i][1] - m[1];
      cand.emplace_back(dx * dx + dy * dy, i);
    }
    std::sort(cand.begin(), cand.end());
    std::size_t pick = xy.size();
    for (const auto& [d2, i] : cand) {
      bool clear = true;
      for (std::size_t a = 0; a < xy.size() && clear; ++a)
        clear = !crosses(m, xy[i], xy[a], xy[(a + 1) % xy.size()]) && !on_segment(m, xy[i], xy[a]);
      for (std::size_t g = 0; g < holes_xy.size() && clear; ++g) {
        if (done[g]) continue;
        const auto& l = holes_xy[g];
        for (std::size_t a = 0; a < l.size() && clear; ++a)
          clear = !crosses(m, xy[i], l[a], l[(a + 1) % l.size()]) && !on_segment(m, xy[i], l[a]);
      }
      if (clear) {
        pick = i;
        break;
      }
    }
    if (pick == xy.size()) return false;
    // Splice: ..., P, M, hole after M ..., M, P, ...
    std::vector<P2> nxy(xy.begin(), xy.begin() + static_cast<std::ptrdiff_t>(pick + 1));
    std::vector<std::uint32_t> nid(id.begin(), id.begin() + static_cast<std::ptrdiff_t>(pick + 1));
    const std::size_t hn = holes_xy[h].size();
    for (std::size_t k = 0; k <= hn; ++k) {
      nxy.push_back(holes_xy[h][(right[h] + k) % hn]);
      nid.push_back(holes_id[h][(right[h] + k) % hn]);
    }
    nxy.push_back(xy[pick]);
    nid.push_back(id[pick]);
    nxy.insert(nxy.end(), xy.begin() + static_cast<std::ptrdiff_t>(pick + 1), xy.end());
    nid.insert(nid.end(), id.begin() + static_cast<std::ptrdiff_t>(pick + 1), id.end());
    xy.swap(nxy);
    id.swap(nid);
    done[h] = 1;
  }
  // Ear clipping over a ring of positions in xy.
  ring.resize(xy.size());
  std::iota(ring.begin(), ring.end(), std::size_t{0});
  while (ring.size() > 3) {
    const std::size_t n = ring.size();
    std::size_t best = n;
    double best_turn = -1e300;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t a = ring[(i + n - 1) % n], b = ring[i], c = ring[(i + 1) % n];
      if (id[a] == id[b] || id[b] == id[c] || id[a] == id[c]) continue;
      const double turn = orient(xy[a], xy[b], xy[c]);
      if (turn > 0) {
        bool empty = true;
        for (std::size_t r : ring) {
          if (id[r] == id[a] || id[r] == id[b] || id[r] == id[c]) continue;
          if (orient(xy[a], xy[b], xy[r]) >= 0 && orient(xy[b], xy[c], xy[r]) >= 0 &&
              orient(xy[c], xy[a], xy[r]) >= 0) {
            empty = false;
            break;
          }
        }
        if (empty) {
          best = i;
          break;
        }
      }
      if (turn > best_turn) {
        best_turn = turn;
        best = i;
      }
    }
    if (best == n) return false;
    tris.push_back({id[ring[(best + n - 1) % n]], id[ring[best]], id[ring[(best + 1) % n]]});
    ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(best));
  }
  if (ring.size() == 3) {
    if (id[ring[0]] == id[ring[1]] || id[ring[1]] == id[ring[2]] || id[ring[0]] == id[ring[2]]) return false;
    tris.push_back({id[ring[0]], id[ring[1]], id[ring[2]]});
  }
  return true;
}

}  // namespace hedge::solid_detail
