// to_indexed(): SurfaceMesh -> index buffers, with optional triangulation and winding flip.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "hedge/core/build.h"

namespace hedge {

namespace {

// Exact-value deduplication of attribute values into a pool.
template <typename T>
class Pool {
 public:
  explicit Pool(std::vector<T>& out) : out_(out) {}
  Index add(const T& v) {
    std::string key(reinterpret_cast<const char*>(&v), sizeof(T));
    auto [it, inserted] = index_.try_emplace(std::move(key), static_cast<Index>(out_.size()));
    if (inserted) out_.push_back(v);
    return it->second;
  }

 private:
  std::vector<T>& out_;
  std::unordered_map<std::string, Index> index_;
};

// Ear clipping of one polygon (corner positions p) in its Newell plane. Writes corner-index
// triples into tris. Falls back to a fan where no ear can be found (self-intersecting input).
void ear_clip(const std::vector<Vec3d>& p, std::vector<std::array<Index, 3>>& tris) {
  const std::size_t n = p.size();
  Vec3d nrm{0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3d& a = p[i];
    const Vec3d& b = p[(i + 1) % n];
    nrm.x += (a.y - b.y) * (a.z + b.z);
    nrm.y += (a.z - b.z) * (a.x + b.x);
    nrm.z += (a.x - b.x) * (a.y + b.y);
  }
  // Project onto the plane: drop the dominant normal axis, keeping orientation.
  int ax = 0;
  if (std::abs(nrm.y) > std::abs(nrm[ax])) ax = 1;
  if (std::abs(nrm.z) > std::abs(nrm[ax])) ax = 2;
  const int u = (ax + 1) % 3, v = (ax + 2) % 3;
  const double sign = nrm[ax] < 0 ? -1.0 : 1.0;
  std::vector<std::array<double, 2>> q(n);
  for (std::size_t i = 0; i < n; ++i) q[i] = {p[i][u], sign * p[i][v]};
  auto cross2 = [&](Index a, Index b, Index c) {
    return (q[b][0] - q[a][0]) * (q[c][1] - q[a][1]) - (q[b][1] - q[a][1]) * (q[c][0] - q[a][0]);
  };
  std::vector<Index> ring(n);
  for (std::size_t i = 0; i < n; ++i) ring[i] = static_cast<Index>(i);
  while (ring.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < ring.size() && !clipped; ++i) {
      const Index a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i], c = ring[(i + 1) % ring.size()];
      if (cross2(a, b, c) <= 0) continue;  // reflex or flat corner
      bool inside = false;
      for (Index r : ring) {
        if (r == a || r == b || r == c) continue;
        if (cross2(a, b, r) >= 0 && cross2(b, c, r) >= 0 && cross2(c, a, r) >= 0) { inside = true; break; }
      }
      if (inside) continue;
      tris.push_back({a, b, c});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) break;
  }
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) tris.push_back({ring[0], ring[i], ring[i + 1]});
}

}  // namespace

IndexedMesh to_indexed(const SurfaceMesh& mesh, const ExportOptions& opt, std::vector<Index>* vertex_map) {
  IndexedMesh out;
  std::vector<Index> vmap(mesh.vertices_size(), kInvalidIndex);
  out.positions.reserve(mesh.n_vertices());
  for (Vertex v : mesh.vertices()) {
    vmap[v.idx()] = static_cast<Index>(out.positions.size());
    out.positions.push_back(mesh.position(v));
  }

  const auto uv = opt.corner_attributes ? mesh.get_halfedge_property<Vec2>("h:texcoord") : HalfedgeProperty<Vec2>();
  const auto nrm = opt.corner_attributes ? mesh.get_halfedge_property<Vec3>("h:normal") : HalfedgeProperty<Vec3>();
  Pool<Vec2> uv_pool(out.texcoords);
  Pool<Vec3> nrm_pool(out.normals);

  const bool polygons = opt.triangulation == Triangulation::none && !mesh.is_triangle_mesh();
  out.indices.reserve(3 * mesh.n_faces());
  std::vector<Halfedge> corner;  // corner i of the face is the target of corner[i]
  std::vector<Vec3d> pts;
  std::vector<std::array<Index, 3>> tris;

  auto emit = [&](Halfedge h) {
    out.indices.push_back(vmap[mesh.to_vertex(h).idx()]);
    if (uv) out.texcoord_indices.push_back(uv_pool.add(uv[h]));
    if (nrm) out.normal_indices.push_back(nrm_pool.add(nrm[h]));
  };

  for (Face f : mesh.faces()) {
    corner.clear();
    // halfedge(f) enters the face's first corner, so the order given at build time is kept.
    for (Halfedge h : mesh.halfedges(f)) corner.push_back(h);
    if (opt.winding == Winding::cw) std::reverse(corner.begin() + 1, corner.end());
    const std::size_t n = corner.size();
    if (polygons || n == 3) {
      for (Halfedge h : corner) emit(h);
      if (polygons) out.face_sizes.push_back(static_cast<Index>(n));
      continue;
    }
    tris.clear();
    if (opt.triangulation == Triangulation::ear) {
      pts.clear();
      for (Halfedge h : corner) pts.push_back(to_double(mesh.position(mesh.to_vertex(h))));
      ear_clip(pts, tris);
    } else {
      for (std::size_t i = 1; i + 1 < n; ++i)
        tris.push_back({0, static_cast<Index>(i), static_cast<Index>(i + 1)});
    }
    for (const auto& t : tris)
      for (Index i : t) emit(corner[i]);
  }
  if (vertex_map) *vertex_map = std::move(vmap);
  return out;
}

}  // namespace hedge
