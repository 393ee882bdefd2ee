// build(): index buffers -> SurfaceMesh in O(n).
//
// Clean input takes two passes over the corners:
//  - pair_fast() finds twins without hashing: each undirected edge lives in a table line of its
//    smaller vertex (one cache line per vertex, scanned with a few SIMD compares), so the second
//    corner of an edge finds the first one there. Edges are numbered as their first corner comes
//    up, so a face's half-edges sit together in memory, as a scan of the input would visit them;
//  - link() writes the mesh arrays from the corners and, on triangles, walks every vertex fan
//    soon after the vertex's last corner is linked, which checks that each vertex is manifold
//    (polygons get a separate pass for that).
// An edge that is not a simple manifold edge, or a degenerate face, sends the pairing to the
// general path (bucketing by smaller vertex, then sorting each bucket), which handles every
// defect: the repair steps (re-orientation, cutting non-manifold edges, splitting vertex fans) or,
// under the strict policy, an error that names the offending input elements.
//
// The large passes are memory-bound on big meshes, hence the software prefetches ahead of the
// scattered accesses and the huge-page advice on the large arrays.
//
// Each step lives in its own file; build_internal.h lists them.
#include "hedge/core/build.h"

#include <string>
#include <vector>

#include "build_internal.h"
#include "hedge/core/properties.h"
#include "hedge/error.h"

namespace hedge {

using build_detail::EdgeGroups;
using build_detail::for_each_corner;

namespace build_detail {

std::string list_str(const std::vector<std::string>& items, std::size_t total) {
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? "; " : "") + items[i];
  if (total > items.size()) s += "; and " + std::to_string(total - items.size()) + " more";
  return s;
}

}  // namespace build_detail

void MeshBuilder::attach_attributes(SurfaceMesh& m) const {
  if (!opt_.corner_attributes) return;
  auto origin = [&](Index c) { return f_.corner_origin.empty() ? c : f_.corner_origin[c]; };
  // The attribute of corner cn (a vertex of face f) is stored on the half-edge entering it: the
  // half-edge of the corner before it.
  if (!in_.texcoord_indices.empty()) {
    auto uv = m.halfedge_property<Vec2>("h:texcoord");
    for_each_corner(f_, [&](Index c, Index cn, Index) {
      uv[Halfedge(corner_he_[c])] = in_.texcoords[in_.texcoord_indices[origin(cn)]];
    });
  }
  if (!in_.normal_indices.empty()) {
    auto nrm = m.halfedge_property<Vec3>("h:normal");
    for_each_corner(f_, [&](Index c, Index cn, Index) {
      nrm[Halfedge(corner_he_[c])] = in_.normals[in_.normal_indices[origin(cn)]];
    });
  }
  if (!in_.color_indices.empty()) {
    auto col = m.halfedge_property<Color>("h:color");
    for_each_corner(f_, [&](Index c, Index cn, Index) {
      col[Halfedge(corner_he_[c])] = in_.colors[in_.color_indices[origin(cn)]];
    });
  }
}

SurfaceMesh MeshBuilder::run() {
  check_input();
  weld();
  Paired paired = pair_fast(clean_faces());
  if (paired == Paired::degenerate) {
    clean_faces_general();
    paired = pair_fast(false);
  }
  if (paired != Paired::ok) {
    EdgeGroups groups = group_edges();
    if (!pair_corners(groups, false)) {
      if (opt_.policy == TopologyPolicy::strict) throw TopologyError(problems_, bad_vertices_);
      problems_.clear();
      bad_vertices_.clear();
      reorient(groups);
      groups = group_edges();
      pair_corners(groups, true);
    }
    number_edges();
  }

  SurfaceMesh m;
  link(m);
  if (!(fans_checked_ ? fans_simple_ : fans_are_simple(m))) {
    split_fans(m);
    if (!problems_.empty()) throw TopologyError(problems_, bad_vertices_);
    // The walks listed the boundary half-edges of the fans they saw; the split ones need all.
    boundary_hes_.clear();
    for (Index h = 0; h < m.halfedge_slots(); ++h)
      if (m.is_boundary(Halfedge(h))) boundary_hes_.push_back(h);
  }
  link_boundaries(m);
  attach_attributes(m);
  if (rep_.duplicated_vertices > 0) m.shrink_to_fit();
  if (!want_maps_) return m;

  // Maps for the caller.
  const Index nv = n_vertices();
  const std::size_t n_in = in_.positions.size();
  rep_.vertex_map.resize(n_in);
  for (std::size_t i = 0; i < n_in; ++i) rep_.vertex_map[i] = weld_map_.empty() ? Index(i) : weld_map_[i];
  rep_.vertex_origin.resize(m.vertex_slots());
  for (Index v = 0; v < nv; ++v) rep_.vertex_origin[v] = input_vertex(v);
  for (std::size_t i = 0; i < vertex_origin_.size(); ++i)
    rep_.vertex_origin[nv + i] = input_vertex(vertex_origin_[i]);
  rep_.face_map.assign(in_.face_count(), kInvalidIndex);
  for (Index f = 0; f < f_.n_faces; ++f) rep_.face_map[f_.face_origin.empty() ? f : f_.face_origin[f]] = f;
  return m;
}

SurfaceMesh build(const IndexedMesh& input, const BuildOptions& options, BuildReport* report) {
  BuildInput view{input.positions,      input.indices,          input.face_sizes,
                  input.texcoords,      input.texcoord_indices, input.normals,
                  input.normal_indices, input.colors,           input.color_indices};
  BuildReport local;
  BuildReport& rep = report ? *report : local;
  rep = BuildReport{};
  const std::vector<std::int32_t>& submeshes = input.face_submeshes;
  if (submeshes.empty()) return MeshBuilder(view, options, rep, report != nullptr).run();
  if (submeshes.size() != input.face_count())
    throw InvalidInputError("indexed mesh: " + std::to_string(submeshes.size()) + " face submeshes for " +
                            std::to_string(input.face_count()) + " faces");
  for (std::size_t f = 0; f < submeshes.size(); ++f)
    if (submeshes[f] < 0 || submeshes[f] > kMaxSubmesh)
      throw InvalidInputError("indexed mesh: face " + std::to_string(f) + " has submesh " +
                              std::to_string(submeshes[f]) + ", outside [0, " + std::to_string(kMaxSubmesh) +
                              "]");
  // The face map carries each kept face's submesh to the face it became.
  SurfaceMesh mesh = MeshBuilder(view, options, rep, true).run();
  auto submesh = mesh.face_property<std::int32_t>(kSubmeshProperty);
  for (std::size_t f = 0; f < submeshes.size(); ++f)
    if (rep.face_map[f] != kInvalidIndex) submesh[Face(rep.face_map[f])] = submeshes[f];
  return mesh;
}

SurfaceMesh build_triangles(std::span<const Vec3> positions, std::span<const std::uint32_t> triangles,
                            const BuildOptions& options, BuildReport* report) {
  BuildInput view{positions, triangles, {}, {}, {}, {}, {}, {}, {}};
  BuildReport local;
  BuildReport& rep = report ? *report : local;
  rep = BuildReport{};
  return MeshBuilder(view, options, rep, report != nullptr).run();
}

}  // namespace hedge
