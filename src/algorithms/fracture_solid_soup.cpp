// Solid fracture: the soup of the broken region's triangles, its grid and its vertices' numbers.
#include "fracture_solid_soup.h"

#include <algorithm>
#include <cmath>

#include "hedge/core/triangulate.h"

namespace hedge::solid_detail {

//! The soup: every face of `faces` as triangles, a polygon as its fan from fan_start() (as
//! volume() and the picking tree see it: from the first corner unless that fan folds).
std::vector<SoupTriangle> make_soup(const SurfaceMesh& mesh, const std::vector<Face>& faces) {
  std::vector<SoupTriangle> soup;
  std::vector<Halfedge> hs;
  for (Face f : faces) {
    hs.clear();
    const Halfedge start = fan_start(mesh, f);
    Halfedge h = start;
    do {
      hs.push_back(h);
      h = mesh.next(h);
    } while (h != start);
    for (std::size_t k = 1; k + 1 < hs.size(); ++k) {
      SoupTriangle s;
      s.face = f;
      const std::array<Halfedge, 3> c{hs[0], hs[k], hs[k + 1]};
      for (int i = 0; i < 3; ++i) {
        s.corner[i] = c[i];
        s.v[i] = mesh.to_vertex(c[i]).idx();
        const Vec3& p = mesh.position(Vertex(s.v[i]));
        for (int a = 0; a < 3; ++a) {
          s.lo[a] = i == 0 ? p[a] : std::min(s.lo[a], p[a]);
          s.hi[a] = i == 0 ? p[a] : std::max(s.hi[a], p[a]);
        }
      }
      soup.push_back(s);
    }
  }
  return soup;
}

//! A grid of about sqrt(soup.size()) / 2 cells along the box's widest side (at most 32): a surface
//! through the box meets a few triangles per grid cell.
SoupGrid grid_soup(const std::vector<SoupTriangle>& soup) {
  SoupGrid grid;
  if (soup.empty()) {
    grid.first.assign(2, 0);
    return grid;
  }
  float lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = soup[0].lo[a];
    hi[a] = soup[0].hi[a];
  }
  for (const SoupTriangle& t : soup)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], t.lo[a]);
      hi[a] = std::max(hi[a], t.hi[a]);
    }
  const double side = std::clamp(std::sqrt(double(soup.size())) / 2, 1.0, 32.0);
  double widest = 0;
  for (int a = 0; a < 3; ++a) widest = std::max(widest, double(hi[a]) - lo[a]);
  for (int a = 0; a < 3; ++a) {
    const double extent = double(hi[a]) - lo[a];
    grid.origin[a] = lo[a];
    grid.n[a] = widest > 0 ? std::max(1, int(std::ceil(side * extent / widest))) : 1;
    grid.scale[a] = extent > 0 ? grid.n[a] / extent : 0;
  }
  const std::size_t cells = std::size_t(grid.n[0]) * grid.n[1] * grid.n[2];
  grid.first.assign(cells + 1, 0);
  // Most triangles fall in one grid cell: (triangle, cell) pairs in soup order, counted per cell,
  // then placed.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  pairs.reserve(soup.size() + soup.size() / 2);
  for (std::uint32_t i = 0; i < soup.size(); ++i)
    grid.for_buckets(soup[i].lo, soup[i].hi, [&](std::size_t b) {
      pairs.emplace_back(i, static_cast<std::uint32_t>(b));
      ++grid.first[b + 1];
    });
  for (std::size_t b = 0; b < cells; ++b) grid.first[b + 1] += grid.first[b];
  grid.items.resize(pairs.size());
  std::vector<std::uint32_t> fill(grid.first.begin(), grid.first.end() - 1);
  for (const auto& [i, b] : pairs) grid.items[fill[b]++] = i;
  return grid;
}

SoupIndex index_soup(const std::vector<SoupTriangle>& soup) {
  SoupIndex x;
  // Mesh vertex -> number, in the order of first use.
  NumberTable<Index, HashIndex> table(2 * soup.size());
  x.corner.resize(soup.size());
  for (std::size_t t = 0; t < soup.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto next = static_cast<std::uint32_t>(x.vertices.size());
      const std::uint32_t n = table.find_or_add(soup[t].v[k], next);
      if (n == next) x.vertices.push_back(soup[t].v[k]);
      x.corner[t][k] = n;
    }
  return x;
}

}  // namespace hedge::solid_detail
