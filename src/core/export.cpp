// to_indexed(): SurfaceMesh -> index buffers, with optional triangulation and winding flip.
#include "hedge/core/export.h"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "hedge/core/properties.h"
#include "hedge/core/triangulate.h"

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

}  // namespace

IndexedMesh to_indexed(const SurfaceMesh& mesh, const ExportOptions& opt, std::vector<Index>* vertex_map) {
  IndexedMesh out;
  std::vector<Index> vmap(mesh.vertex_slots(), kInvalidIndex);
  out.positions.reserve(mesh.n_vertices());
  for (Vertex v : mesh.vertices()) {
    vmap[v.idx()] = static_cast<Index>(out.positions.size());
    out.positions.push_back(mesh.position(v));
  }

  const auto uv =
      opt.corner_attributes ? mesh.get_halfedge_property<Vec2>("h:texcoord") : HalfedgeProperty<Vec2>();
  const auto nrm =
      opt.corner_attributes ? mesh.get_halfedge_property<Vec3>("h:normal") : HalfedgeProperty<Vec3>();
  Pool<Vec2> uv_pool(out.texcoords);
  const auto col =
      opt.corner_attributes ? mesh.get_halfedge_property<Color>("h:color") : HalfedgeProperty<Color>();
  Pool<Vec3> nrm_pool(out.normals);
  Pool<Color> col_pool(out.colors);
  const auto submesh = mesh.get_face_property<std::int32_t>(kSubmeshProperty);

  const bool polygons = opt.triangulation == Triangulation::none && !mesh.is_triangle_mesh();
  out.indices.reserve(3 * mesh.n_faces());
  std::vector<Halfedge> corner;  // corner i of the face is the target of corner[i]
  std::vector<Vec3d> pts;
  std::vector<std::array<Index, 3>> tris;

  auto emit = [&](Halfedge h) {
    out.indices.push_back(vmap[mesh.to_vertex(h).idx()]);
    if (uv) out.texcoord_indices.push_back(uv_pool.add(uv[h]));
    if (nrm) out.normal_indices.push_back(nrm_pool.add(nrm[h]));
    if (col) out.color_indices.push_back(col_pool.add(col[h]));
  };

  for (Face f : mesh.faces()) {
    corner.clear();
    // halfedge(f) enters the face's first corner, so the order given at build time is kept.
    for (Halfedge h : mesh.halfedges(f)) corner.push_back(h);
    // A fan starts from the corner fan_start() names: the first unless that fan folds.
    if (!polygons && opt.triangulation == Triangulation::fan && corner.size() > 3)
      std::rotate(corner.begin(), std::find(corner.begin(), corner.end(), fan_start(mesh, f)), corner.end());
    if (opt.winding == Winding::cw) std::reverse(corner.begin() + 1, corner.end());
    const std::size_t n = corner.size();
    if (polygons || n == 3) {
      for (Halfedge h : corner) emit(h);
      if (polygons) out.face_sizes.push_back(static_cast<Index>(n));
      if (submesh) out.face_submeshes.push_back(submesh[f]);
      continue;
    }
    tris.clear();
    if (opt.triangulation == Triangulation::ear) {
      pts.clear();
      for (Halfedge h : corner) pts.push_back(to_double(mesh.position(mesh.to_vertex(h))));
      triangulate_polygon(pts, tris);
    } else {
      for (std::size_t i = 1; i + 1 < n; ++i)
        tris.push_back({0, static_cast<Index>(i), static_cast<Index>(i + 1)});
    }
    for (const auto& t : tris)
      for (Index i : t) emit(corner[i]);
    if (submesh) out.face_submeshes.insert(out.face_submeshes.end(), tris.size(), submesh[f]);
  }
  if (vertex_map) *vertex_map = std::move(vmap);
  return out;
}

}  // namespace hedge
