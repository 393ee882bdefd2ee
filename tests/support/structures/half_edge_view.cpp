#include "half_edge_view.h"

namespace hedge::structures {

HalfEdgeView HalfEdgeView::build(std::span<const Vec3> positions, std::span<const Index> triangles,
                                 BuildReport* report) {
  BuildOptions options;
  options.corner_attributes = false;
  HalfEdgeView view;
  view.mesh_ = build_triangles(positions, triangles, options, report);
  return view;
}

std::vector<HalfEdgeView::EdgeRef> HalfEdgeView::edge_list() const {
  std::vector<EdgeRef> edges;
  edges.reserve(mesh_.n_edges());
  for (Edge e : mesh_.edges()) edges.push_back(e.idx());
  return edges;
}

}  // namespace hedge::structures
