// Splitting every face. See include/hedge/algorithms/split_all_faces.h for the contract.
#include "hedge/algorithms/split_all_faces.h"

#include "hedge/algorithms/subdivide.h"
#include "hedge/core/face_operations.h"

namespace hedge {

std::vector<Vertex> split_all_faces(SurfaceMesh& m) {
  require_finite_positions(m, "split_all_faces");
  std::vector<Vertex> out;
  out.reserve(m.n_faces());
  if (!m.has_garbage()) {
    const Index first = Index(m.vertex_slots()), faces = Index(m.face_slots());
    subdivide(m, Subdivision::split_faces, 1);
    for (Index f = 0; f < faces; ++f) out.push_back(Vertex(first + f));
    return out;
  }
  std::vector<Face> faces;
  for (Face f : m.faces()) faces.push_back(f);
  m.changes().begin();  // one notification for the whole pass
  for (Face f : faces) out.push_back(split_face(m, f, face_centroid(m, f)));
  m.changes().commit();
  return out;
}

}  // namespace hedge
