// Splitting every face. See include/hedge/algorithms/split_all_faces.h for the contract.
#include "hedge/algorithms/split_all_faces.h"

#include "hedge/core/operations.h"

namespace hedge {

std::vector<Vertex> split_all_faces(SurfaceMesh& m) {
  std::vector<Face> faces;
  for (Face f : m.faces()) faces.push_back(f);
  std::vector<Vertex> out;
  out.reserve(faces.size());
  m.changes().begin();  // one notification for the whole pass
  for (Face f : faces) out.push_back(split_face(m, f, face_centroid(m, f)));
  m.changes().commit();
  return out;
}

}  // namespace hedge
