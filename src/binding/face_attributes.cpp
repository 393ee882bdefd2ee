#include "binding/face_attributes.h"

#include <string>

#include "binding/edits.h"
#include "binding/errors.h"
#include "hedge/core/face_operations.h"

namespace hedge::binding {

namespace {
constexpr const char* kTexcoord = "h:texcoord";

// Fails unless the property `name` is absent or of type T.
template <typename T>
void need_type(const PropertyContainer& properties, const char* name, const char* type) {
  if (properties.find_base(name) != nullptr && properties.get<T>(name) == nullptr)
    fail(HEDGE_ERROR_INVALID_ARGUMENT, std::string("the mesh's \"") + name + "\" is not of type " + type +
                                           ", as add_face's attributes need");
}

// Every check of the attributes, before the mesh changes.
void check(const SurfaceMesh& m, std::size_t corners, const FaceAttributes& a) {
  if (!a.texcoords.empty()) {
    if (a.texcoords.size() != corners)
      fail(HEDGE_ERROR_INVALID_ARGUMENT, "add_face: " + std::to_string(a.texcoords.size()) +
                                             " texcoords for " + std::to_string(corners) + " corners");
    for (std::size_t i = 0; i < a.texcoords.size(); ++i)
      if (!is_finite(a.texcoords[i]))
        fail(HEDGE_ERROR_INVALID_ARGUMENT, "add_face: texcoord " + std::to_string(i) + " is not finite");
    if (m.vertex_properties().find_base("v:texcoord") != nullptr &&
        m.halfedge_properties().find_base(kTexcoord) == nullptr)
      fail(HEDGE_ERROR_INVALID_ARGUMENT,
           "add_face: the mesh keeps its texcoords per vertex (\"v:texcoord\"), not per corner "
           "(\"h:texcoord\")");
    need_type<Vec2>(m.halfedge_properties(), kTexcoord, "Vec2");
  }
  if (a.submesh) {
    if (*a.submesh < 0 || *a.submesh > kMaxSubmesh)
      fail(HEDGE_ERROR_INVALID_ARGUMENT, "add_face: submesh " + std::to_string(*a.submesh) +
                                             " is not in [0, " + std::to_string(kMaxSubmesh) + "]");
    need_type<std::int32_t>(m.face_properties(), kSubmeshProperty, "int32");
  }
}
}  // namespace

Face add_face(SurfaceMesh& m, std::span<const Vertex> corners, const FaceAttributes& attributes) {
  check(m, corners.size(), attributes);
  const Face f = binding::add_face(m, corners);  // refused: nothing changed yet
  if (!attributes.texcoords.empty()) {
    auto texcoord = m.halfedge_property<Vec2>(kTexcoord);
    // The corner of corners[i] in f is stored on the half-edge of f that enters it.
    for (const Halfedge h : m.halfedges(f))
      for (std::size_t i = 0; i < corners.size(); ++i)
        if (corners[i] == m.to_vertex(h)) texcoord[h] = attributes.texcoords[i];
  }
  if (attributes.submesh) m.face_property<std::int32_t>(kSubmeshProperty)[f] = *attributes.submesh;
  m.mark_changed(f);
  return f;
}

}  // namespace hedge::binding
