// Detaching faces. See include/hedge/algorithms/detach_faces.h for the contract.
#include "hedge/algorithms/detach_faces.h"

#include <algorithm>

#include "hedge/core/build.h"
#include "hedge/core/face_operations.h"

namespace hedge {

SurfaceMesh detach_faces(SurfaceMesh& m, std::span<const Face> faces_in, std::vector<Vertex>* vertex_origin) {
  std::vector<Face> faces;
  for (Face f : faces_in)
    if (m.is_live(f)) faces.push_back(f);
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());

  // The set as an indexed mesh over its own vertices.
  std::vector<Vertex> verts;
  for (Face f : faces)
    for (Vertex v : m.vertices(f)) verts.push_back(v);
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  auto local = [&](Vertex v) {
    return static_cast<Index>(std::lower_bound(verts.begin(), verts.end(), v) - verts.begin());
  };
  IndexedMesh part;
  for (Vertex v : verts) part.positions.push_back(m.position(v));
  std::vector<Halfedge> corner_src;
  for (Face f : faces) {
    std::size_t n = 0;
    for (Halfedge h : m.halfedges(f)) {
      part.indices.push_back(local(m.to_vertex(h)));
      corner_src.push_back(h);
      ++n;
    }
    part.face_sizes.push_back(static_cast<Index>(n));
  }
  BuildOptions opt;
  opt.policy = TopologyPolicy::repair;  // faces of the set may touch at a vertex only
  BuildReport rep;
  SurfaceMesh out = build(part, opt, &rep);

  // Every property comes along.
  out.vertex_properties().add_missing_from(m.vertex_properties());
  out.halfedge_properties().add_missing_from(m.halfedge_properties());
  out.edge_properties().add_missing_from(m.edge_properties());
  out.face_properties().add_missing_from(m.face_properties());
  std::vector<Vertex> origin(out.vertex_slots());
  for (Vertex v : out.vertices()) {
    origin[v.idx()] = verts[rep.vertex_origin[v.idx()]];
    out.vertex_properties().copy_element_from(m.vertex_properties(), origin[v.idx()].idx(), v.idx());
  }
  std::size_t c = 0;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const Face nf(rep.face_map[i]);
    out.face_properties().copy_element_from(m.face_properties(), faces[i].idx(), nf.idx());
    for (Halfedge h : out.halfedges(nf)) {
      const Halfedge src = corner_src[c++];
      out.halfedge_properties().copy_element_from(m.halfedge_properties(), src.idx(), h.idx());
      out.edge_properties().copy_element_from(m.edge_properties(), SurfaceMesh::edge(src).idx(),
                                              SurfaceMesh::edge(h).idx());
    }
  }
  remove_faces(m, faces);
  if (vertex_origin) *vertex_origin = std::move(origin);
  return out;
}

}  // namespace hedge
