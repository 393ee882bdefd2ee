#include "raster.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "colors.h"
#include "hedge/algorithms/components.h"
#include "hedge/algorithms/curvature.h"
#include "hedge/algorithms/fracture_solid.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/core/threads.h"
#include "hedge/error.h"

namespace hedge::picture {

namespace {

struct Screen {
  float x, y;
  float key;  // larger is nearer: 1 / depth (perspective) or -depth (orthographic), both linear in x, y
  bool usable;
};

// A fan triangle of a face, with what to draw along each of its sides (side j is opposite corner j).
struct Tri {
  Index v[3];
  Index face;
  std::uint8_t side[3];
};

enum EdgeClass : std::uint8_t { kNoLine = 0, kWire = 1, kFeature = 2, kBoundary = 3 };

// A diverging scale: -1 blue, 0 near white, +1 red.
Rgb diverging(double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, -1.0, 1.0);
  const Rgb lo{59, 76, 192}, mid{235, 235, 235}, hi{200, 40, 40};
  const Rgb& e = t < 0 ? lo : hi;
  const double s = std::abs(t);
  return mix(mid, e, s);
}

struct Prepared {
  std::vector<Screen> screen;
  std::vector<Tri> tris;
  std::vector<Vec3> face_normal;    // per face slot, twice the area long (Newell's)
  std::vector<Vec3> vertex_normal;  // unit, per vertex slot (smooth shading)
  std::vector<Rgb> face_color;      // per face slot
  std::vector<Rgb> vertex_color;    // per vertex slot, when colours vary per vertex
};

// Runs fn(begin, end, chunk) over at most `threads` chunks of [0, n) in parallel (one chunk when n
// is small), by the library's parallel-for. fn must not throw.
template <typename Fn>
void parallel_for(std::size_t n, unsigned threads, Fn&& fn) {
  detail::parallel_ranges(n, fn, 8192, threads);
}

Prepared prepare(const SurfaceMesh& m, const Projection& proj, const RenderOptions& o, int s,
                 unsigned threads) {
  Prepared p;
  const std::size_t nv = m.vertex_slots(), nf = m.face_slots();
  p.screen.assign(nv, Screen{0, 0, 0, false});
  std::vector<Index> first_bad(threads, kInvalidIndex);  // per chunk: the first non-finite position
  parallel_for(nv, threads, [&](std::size_t b, std::size_t e, unsigned k) {
    for (std::size_t i = b; i < e; ++i) {
      if (m.is_deleted(Vertex(Index(i)))) continue;
      const Vec3 q = m.position(Vertex(Index(i)));
      if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) {
        first_bad[k] = std::min(first_bad[k], Index(i));
        continue;
      }
      const Projection::Point sp = proj(to_double(q));
      const bool usable = proj.orthographic() || sp.depth > 1e-9;
      const double key = proj.orthographic() ? -sp.depth : 1 / sp.depth;
      p.screen[i] = {float(sp.x * s), float(sp.y * s), float(key),
                     usable && std::isfinite(sp.x) && std::isfinite(sp.y)};
    }
  });
  const Index bad = *std::min_element(first_bad.begin(), first_bad.end());
  if (bad != kInvalidIndex)
    throw InvalidInputError("vertex " + std::to_string(bad) + " has a position that is not finite");

  // Face normals (Newell's, area-weighted), then unit vertex normals gathered from them. Floats:
  // these arrays are large, and filling fresh memory costs more than the arithmetic.
  p.face_normal.assign(nf, Vec3{0, 0, 0});
  parallel_for(nf, threads, [&](std::size_t b, std::size_t e, unsigned) {
    for (std::size_t i = b; i < e; ++i)
      if (!m.is_deleted(Face(Index(i)))) p.face_normal[i] = to_float(area_vector(m, Face(Index(i))));
  });
  if (o.shading == Shading::smooth) {
    p.vertex_normal.assign(nv, Vec3{0, 0, 0});
    parallel_for(nv, threads, [&](std::size_t b, std::size_t e, unsigned) {
      for (std::size_t i = b; i < e; ++i) {
        const Vertex v(static_cast<Index>(i));
        if (m.is_deleted(v) || m.is_isolated(v)) continue;
        Vec3d n{0, 0, 0};
        for (Face f : m.faces(v))
          if (f.is_valid()) n += to_double(p.face_normal[f.idx()]);
        p.vertex_normal[i] = to_float(unit_or_zero(n));
      }
    });
  }

  p.face_color.assign(m.face_slots(), o.base);
  if (o.color_by == ColorBy::face) {
    for (Face f : m.faces()) p.face_color[f.idx()] = categorical(f.idx());
  } else if (o.color_by == ColorBy::shard) {
    const Components comp = face_components(m);
    for (Face f : m.faces()) p.face_color[f.idx()] = categorical(comp.label[f.idx()]);
    const auto inner = m.get_face_property<std::uint8_t>(kInnerProperty);
    if (inner)
      for (Face f : m.faces())
        if (inner[f] != 0) p.face_color[f.idx()] = o.inner_color;
  } else if (o.color_by == ColorBy::valence) {
    p.vertex_color.assign(m.vertex_slots(), o.base);
    // Regular valence from the faces around: a corner of a regular n-gon spans pi (n - 2) / n, so
    // 6 around a vertex of triangles, 4 of quads; half as many at a boundary.
    for (Vertex v : m.vertices()) {
      double angle = 0;
      std::size_t n = 0;
      for (Face f : m.faces(v)) {
        if (!f.is_valid()) continue;
        const double sides = double(m.valence(f));
        angle += std::numbers::pi * (sides - 2) / sides;
        ++n;
      }
      if (n == 0) continue;
      const double regular =
          (m.is_boundary(v) ? std::numbers::pi : 2 * std::numbers::pi) / (angle / double(n));
      p.vertex_color[v.idx()] = diverging((double(m.valence(v)) - regular) / 3);
    }
  } else if (o.color_by == ColorBy::curvature) {
    const std::vector<double> h = mean_curvature(m);
    std::vector<double> mags;
    for (Vertex v : m.vertices()) mags.push_back(std::abs(h[v.idx()]));
    double scale = 1;
    if (!mags.empty()) {
      const std::size_t k = mags.size() * 95 / 100;
      std::nth_element(mags.begin(), mags.begin() + std::ptrdiff_t(std::min(k, mags.size() - 1)), mags.end());
      scale = mags[std::min(k, mags.size() - 1)];
    }
    if (!(scale > 0)) scale = 1;
    p.vertex_color.assign(m.vertex_slots(), o.base);
    for (Vertex v : m.vertices()) p.vertex_color[v.idx()] = diverging(h[v.idx()] / scale);
  }

  // What each edge is drawn as.
  const double cos_feature = std::cos(o.feature_angle * std::numbers::pi / 180);
  auto edge_class = [&](Halfedge h) -> std::uint8_t {
    const Edge e = SurfaceMesh::edge(h);
    if (m.is_boundary(e)) return o.boundary ? kBoundary : (o.wireframe ? kWire : kNoLine);
    if (o.feature_angle > 0) {
      const Vec3d a = unit_or_zero(to_double(p.face_normal[m.face(h).idx()]));
      const Vec3d b = unit_or_zero(to_double(p.face_normal[m.face(SurfaceMesh::twin(h)).idx()]));
      if (dot(a, b) < cos_feature) return kFeature;
    }
    return o.wireframe ? kWire : kNoLine;
  };
  // The fan triangles, built per chunk of faces and joined in face order.
  std::vector<std::vector<Tri>> chunks(threads);
  parallel_for(nf, threads, [&](std::size_t b, std::size_t e, unsigned k) {
    std::vector<Tri>& out = chunks[k];
    out.reserve((e - b) + (e - b) / 4);
    for (std::size_t i = b; i < e; ++i) {
      const Face f(static_cast<Index>(i));
      if (m.is_deleted(f)) continue;
      const Halfedge h0 = m.halfedge(f);
      const Vertex c0 = m.to_vertex(h0);
      // The face's half-edges: first = next(h0) runs c0 -> c1, then c1 -> c2, ..., and h0 runs
      // c_{n-1} -> c0. Fan triangle i is (c0, c_i, c_{i+1}), made of g: c_i -> c_{i+1}.
      const Halfedge first = m.next(h0);
      const Halfedge second = m.next(first);
      for (Halfedge g = second; g != h0; g = m.next(g)) {
        // Sides: opposite c0 is g; opposite c_i is c_{i+1} -> c0 (h0 in the last triangle);
        // opposite c_{i+1} is c0 -> c_i (first, in the first triangle).
        Tri t;
        t.v[0] = c0.idx();
        t.v[1] = m.from_vertex(g).idx();
        t.v[2] = m.to_vertex(g).idx();
        t.face = f.idx();
        t.side[0] = edge_class(g);
        t.side[1] = m.next(g) == h0 ? edge_class(h0) : std::uint8_t(kNoLine);
        t.side[2] = g == second ? edge_class(first) : std::uint8_t(kNoLine);
        out.push_back(t);
      }
    }
  });
  std::size_t total = 0;
  for (const auto& c : chunks) total += c.size();
  p.tris.reserve(total);
  for (auto& c : chunks) {
    p.tris.insert(p.tris.end(), c.begin(), c.end());
    std::vector<Tri>().swap(c);
  }
  return p;
}

struct Buffers {
  int w = 0, h = 0;
  std::vector<float> key;
  std::vector<Rgb> color;
};

void rasterise_band(const SurfaceMesh& m, const Projection& proj, const Prepared& p, const RenderOptions& o,
                    int s, Buffers& b, int y0, int y1) {
  const Rgb line_colors[4] = {{}, o.wire, o.feature_color, o.boundary_color};
  const float half_width[4] = {0, float(0.5 * o.line_width * s), float(0.75 * o.line_width * s),
                               float(1.0 * o.line_width * s)};
  for (const Tri& t : p.tris) {
    const Screen& A = p.screen[t.v[0]];
    const Screen& B = p.screen[t.v[1]];
    const Screen& C = p.screen[t.v[2]];
    if (!A.usable || !B.usable || !C.usable) continue;
    const float ymin = std::min({A.y, B.y, C.y}), ymax = std::max({A.y, B.y, C.y});
    if (ymax < float(y0) - 0.5f || ymin > float(y1) + 0.5f) continue;
    const double area2 = double(B.x - A.x) * (C.y - A.y) - double(B.y - A.y) * (C.x - A.x);
    if (!(std::abs(area2) > 1e-12)) continue;
    const float xmin = std::min({A.x, B.x, C.x}), xmax = std::max({A.x, B.x, C.x});
    const int ix0 = std::max(0, int(std::floor(xmin - 0.5f))),
              ix1 = std::min(b.w - 1, int(std::ceil(xmax - 0.5f)));
    const int iy0 = std::max(y0, int(std::floor(ymin - 0.5f))),
              iy1 = std::min(y1 - 1, int(std::ceil(ymax - 0.5f)));
    if (ix0 > ix1 || iy0 > iy1) continue;
    const double inv = 1 / area2;
    // The edge functions of the three sides, each evaluated from its lower endpoint (by y, then x)
    // so that the two triangles of a shared side compute exactly opposite values: a sample on the
    // side belongs to both and no sample slips between them.
    struct Side {
      double x, y, dx, dy, sign;
      double operator()(double px, double py) const { return sign * (dx * (py - y) - dy * (px - x)); }
    };
    auto side = [](const Screen& P, const Screen& Q) {
      const bool swap = P.y > Q.y || (P.y == Q.y && P.x > Q.x);
      const Screen& lo = swap ? Q : P;
      const Screen& hi = swap ? P : Q;
      return Side{lo.x, lo.y, double(hi.x) - lo.x, double(hi.y) - lo.y, swap ? -1.0 : 1.0};
    };
    const Side sa = side(B, C), sb = side(C, A), sc = side(A, B);  // opposite A, B, C
    // Distance in samples from the side opposite corner j: w_j * 2 area / |side j|.
    const float len[3] = {std::hypot(C.x - B.x, C.y - B.y), std::hypot(A.x - C.x, A.y - C.y),
                          std::hypot(B.x - A.x, B.y - A.y)};
    const float height[3] = {float(std::abs(area2)) / len[0], float(std::abs(area2)) / len[1],
                             float(std::abs(area2)) / len[2]};
    const bool any_line = t.side[0] | t.side[1] | t.side[2];
    const Vec3 fn = to_float(unit_or_zero(to_double(p.face_normal[t.face])));
    // A head light: from the first corner toward the eye.
    const Vec3 light = o.shading == Shading::unlit
                           ? Vec3{0, 0, 1}
                           : to_float(proj.toward_eye(to_double(m.position(Vertex(t.v[0])))));
    const bool per_vertex_color = !p.vertex_color.empty();
    for (int y = iy0; y <= iy1; ++y) {
      const double py = y + 0.5;
      for (int x = ix0; x <= ix1; ++x) {
        const double px = x + 0.5;
        const double ea = sa(px, py), eb = sb(px, py), ec = sc(px, py);
        if (area2 > 0 ? (ea < 0 || eb < 0 || ec < 0) : (ea > 0 || eb > 0 || ec > 0)) continue;
        const double wa = ea * inv, wb = eb * inv, wc = ec * inv;
        const float key = float(wa * A.key + wb * B.key + wc * C.key);
        const std::size_t i = std::size_t(y) * b.w + x;
        if (!(key > b.key[i])) continue;
        b.key[i] = key;
        if (any_line) {
          const float w[3] = {float(wa), float(wb), float(wc)};
          int best = 0;
          for (int j = 0; j < 3; ++j)
            if (t.side[j] > best && w[j] * height[j] < half_width[t.side[j]]) best = t.side[j];
          if (best != kNoLine) {
            b.color[i] = line_colors[best];
            continue;
          }
        }
        Rgb base;
        if (per_vertex_color) {
          base = mix3(p.vertex_color[t.v[0]], p.vertex_color[t.v[1]], p.vertex_color[t.v[2]], float(wa),
                      float(wb), float(wc));
        } else {
          base = p.face_color[t.face];
        }
        if (o.shading == Shading::unlit) {
          b.color[i] = base;
          continue;
        }
        Vec3 n = fn;
        if (o.shading == Shading::smooth) {
          n = p.vertex_normal[t.v[0]] * float(wa) + p.vertex_normal[t.v[1]] * float(wb) +
              p.vertex_normal[t.v[2]] * float(wc);
          const float l2 = dot(n, n);
          n = l2 > 0 ? n * (1 / std::sqrt(l2)) : fn;
        }
        const float d = std::abs(dot(n, light));
        b.color[i] = scale(base, float(0.22 + 0.78 * d));
      }
    }
  }
}

void draw_marked(const SurfaceMesh& m, const Prepared& p, const RenderOptions& o, int s, Buffers& b) {
  const float r = float(2.5 * o.line_width * s);
  for (Vertex v : o.marked) {
    if (!m.is_live(v)) continue;
    const Screen& c = p.screen[v.idx()];
    if (!c.usable) continue;
    const int cx = int(std::floor(c.x)), cy = int(std::floor(c.y));
    if (cx < 0 || cy < 0 || cx >= b.w || cy >= b.h) continue;
    // Hidden if something clearly nearer covers the vertex's own sample.
    const float here = b.key[std::size_t(cy) * b.w + cx];
    if (here > c.key + 1e-3f * std::abs(c.key)) continue;
    for (int y = std::max(0, int(c.y - r)); y <= std::min(b.h - 1, int(c.y + r)); ++y)
      for (int x = std::max(0, int(c.x - r)); x <= std::min(b.w - 1, int(c.x + r)); ++x)
        if ((x + 0.5f - c.x) * (x + 0.5f - c.x) + (y + 0.5f - c.y) * (y + 0.5f - c.y) <= r * r)
          b.color[std::size_t(y) * b.w + x] = o.marked_color;
  }
}

}  // namespace

Image render(const SurfaceMesh& mesh, const Camera& camera, const RenderOptions& o) {
  check_size(o.width, o.height, "a picture");
  if (o.supersample < 1 || o.supersample > 4)
    throw InvalidInputError("supersample must be in 1..4, got " + std::to_string(o.supersample));
  if (!(o.line_width > 0 && o.line_width <= 64))
    throw InvalidInputError("line width must be in (0, 64] pixels");
  if (!(o.feature_angle >= 0 && o.feature_angle <= 180))
    throw InvalidInputError("the feature angle must be in [0, 180] degrees");
  if (std::int64_t(o.width) * o.height * o.supersample * o.supersample > kMaxPixels)
    throw InvalidInputError("a picture of " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                            " with " + std::to_string(o.supersample * o.supersample) +
                            " samples per pixel needs more than " + std::to_string(kMaxPixels) +
                            " samples; lower the size or the supersampling");
  if (mesh.n_faces() == 0) throw InvalidInputError("nothing to draw: the mesh has no faces");
  const int s = o.supersample;
  const Projection proj(camera, o.width, o.height);
  unsigned threads = o.threads != 0 ? o.threads : max_threads();
  threads = std::clamp(threads, 1u, 16u);
  const Prepared p = prepare(mesh, proj, o, s, threads);

  Buffers b;
  b.w = o.width * s;
  b.h = o.height * s;
  b.key.assign(std::size_t(b.w) * b.h, -std::numeric_limits<float>::infinity());
  b.color.assign(std::size_t(b.w) * b.h, o.background);
  detail::parallel_ranges(
      std::size_t(b.h),
      [&](std::size_t y0, std::size_t y1) { rasterise_band(mesh, proj, p, o, s, b, int(y0), int(y1)); }, 1,
      threads);
  draw_marked(mesh, p, o, s, b);

  Image out(o.width, o.height, o.background);
  const float norm = 1.f / float(s * s);
  for (int y = 0; y < o.height; ++y)
    for (int x = 0; x < o.width; ++x) {
      float acc[3] = {0, 0, 0};
      for (int dy = 0; dy < s; ++dy)
        for (int dx = 0; dx < s; ++dx) {
          const Rgb c = b.color[std::size_t(y * s + dy) * b.w + (x * s + dx)];
          acc[0] += c.r;
          acc[1] += c.g;
          acc[2] += c.b;
        }
      out.set(x, y,
              {std::uint8_t(acc[0] * norm + 0.5f), std::uint8_t(acc[1] * norm + 0.5f),
               std::uint8_t(acc[2] * norm + 0.5f)});
    }
  return out;
}

}  // namespace hedge::picture
