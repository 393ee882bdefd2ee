// from_engine_mesh(): see include/hedge/render/engine_mesh.h. Engine arrays (attributes per
// vertex, seams as duplicated vertices) into a welded SurfaceMesh that keeps the attributes per
// corner.
#include "hedge/render/engine_mesh.h"

#include <cmath>
#include <string>
#include <vector>

#include "hedge/error.h"

namespace hedge {

namespace {
template <typename T>
void check_stream(std::span<const T> s, std::size_t n, const char* name) {
  if (!s.empty() && s.size() != n)
    throw InvalidInputError(std::string("engine mesh: ") + name + " has " + std::to_string(s.size()) +
                            " entries for " + std::to_string(n) + " vertices");
}

bool finite(const Color& c) {
  return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && std::isfinite(c.a);
}

template <typename T, typename Finite>
void check_finite(std::span<const T> s, const char* name, Finite&& ok) {
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!ok(s[i]))
      throw InvalidInputError(std::string("engine mesh: ") + name + " of vertex " + std::to_string(i) +
                              " is not finite");
}
// The map back to the engine arrays: "h:source" per corner (its engine vertex), "v:source" per
// vertex (the first engine vertex welded into it). Elements the edits make later get -1: an
// interpolated index would name an engine vertex they did not come from.
void record_sources(SurfaceMesh& mesh, const std::vector<Index>& origin) {
  auto none = [](const std::int32_t*, const float*, std::size_t) { return std::int32_t{-1}; };
  auto corner = mesh.add_halfedge_property<std::int32_t>(kCornerSource, -1);
  auto vertex = mesh.add_vertex_property<std::int32_t>(kVertexSource, -1);
  corner.set_interpolator(none);
  vertex.set_interpolator(none);
  for (Face f : mesh.faces())
    for (Halfedge h : mesh.halfedges(f)) {
      const auto s = static_cast<std::int32_t>(origin[h.idx()]);
      corner[h] = s;
      std::int32_t& first = vertex[mesh.to_vertex(h)];
      if (first < 0 || s < first) first = s;
    }
}
}  // namespace

SurfaceMesh from_engine_mesh(const EngineMeshView& view, const EngineImportOptions& options,
                             BuildReport* report) {
  const std::size_t n = view.positions.size();
  check_stream(view.normals, n, "normals");
  check_stream(view.texcoords, n, "texcoords");
  check_stream(view.colors, n, "colors");
  check_stream(view.tangents, n, "tangents");
  check_stream(view.texcoords1, n, "texcoords1");
  if (view.indices.size() % 3 != 0)
    throw InvalidInputError("engine mesh: " + std::to_string(view.indices.size()) +
                            " indices is not a whole number of triangles");
  for (std::size_t i = 0; i < view.indices.size(); ++i)
    if (view.indices[i] >= n)
      throw InvalidInputError("engine mesh: index " + std::to_string(i) + " (triangle " +
                              std::to_string(i / 3) + ") is " + std::to_string(view.indices[i]) +
                              ", but there are " + std::to_string(n) + " vertices");
  check_finite(view.normals, "normal", [](const Vec3& v) { return is_finite(v); });
  check_finite(view.texcoords, "texcoord", [](const Vec2& v) { return is_finite(v); });
  check_finite(view.colors, "color", [](const Color& c) { return finite(c); });
  check_finite(view.tangents, "tangent", [](const Vec4& t) { return is_finite(t); });
  check_finite(view.texcoords1, "texcoord1", [](const Vec2& v) { return is_finite(v); });
  const std::size_t triangles = view.indices.size() / 3;
  if (!view.submeshes.empty() && view.submeshes.size() != triangles)
    throw InvalidInputError("engine mesh: submeshes has " + std::to_string(view.submeshes.size()) +
                            " entries for " + std::to_string(triangles) + " triangles");
  for (std::size_t t = 0; t < view.submeshes.size(); ++t)
    if (view.submeshes[t] < 0 || view.submeshes[t] > kMaxSubmesh)
      throw InvalidInputError("engine mesh: submesh of triangle " + std::to_string(t) + " is " +
                              std::to_string(view.submeshes[t]) + ", outside [0, " +
                              std::to_string(kMaxSubmesh) + "]");
  // Positions are checked by build().

  // Each corner carries the index of its engine vertex through the build, encoded exactly in the
  // texcoord channel (16 bits per float); the attributes are then read from the engine arrays.
  IndexedMesh in;
  in.positions.assign(view.positions.begin(), view.positions.end());
  if (options.flip_x)
    for (Vec3& p : in.positions) p.x = -p.x;
  in.indices.assign(view.indices.begin(), view.indices.end());
  if (options.winding == Winding::cw)
    for (std::size_t t = 0; t + 2 < in.indices.size(); t += 3)
      std::swap(in.indices[t + 1], in.indices[t + 2]);
  in.texcoords.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    in.texcoords[i] = {static_cast<float>(i & 0xffffu), static_cast<float>(i >> 16)};
  in.texcoord_indices = in.indices;

  BuildOptions bo;
  bo.policy = options.policy;
  bo.weld = options.weld;
  bo.weld_epsilon = options.weld_epsilon;
  bo.corner_attributes = true;
  BuildReport local;
  BuildReport& rep = report ? *report : local;
  SurfaceMesh mesh = build(in, bo, &rep);

  auto origin_prop = mesh.get_halfedge_property<Vec2>("h:texcoord");
  std::vector<Index> origin(mesh.halfedge_slots(), kInvalidIndex);
  if (origin_prop)
    for (Face f : mesh.faces())
      for (Halfedge h : mesh.halfedges(f)) {
        const Vec2 e = origin_prop[h];
        origin[h.idx()] = static_cast<Index>(e.x) | (static_cast<Index>(e.y) << 16);
      }
  mesh.remove_halfedge_property("h:texcoord");
  record_sources(mesh, origin);

  auto fill = [&](auto prop, auto value_of) {
    for (Face f : mesh.faces())
      for (Halfedge h : mesh.halfedges(f)) prop[h] = value_of(origin[h.idx()]);
  };
  if (!view.texcoords.empty())
    fill(mesh.add_halfedge_property<Vec2>("h:texcoord"), [&](Index i) { return view.texcoords[i]; });
  if (!view.normals.empty())
    fill(mesh.add_halfedge_property<Vec3>("h:normal"), [&](Index i) {
      Vec3 v = view.normals[i];
      if (options.flip_x) v.x = -v.x;
      return v;
    });
  if (!view.colors.empty())
    fill(mesh.add_halfedge_property<Color>("h:color"), [&](Index i) { return view.colors[i]; });
  if (!view.tangents.empty())
    fill(mesh.add_halfedge_property<Vec4>("h:tangent"), [&](Index i) {
      Vec4 t = view.tangents[i];
      if (options.flip_x) {  // a mirror flips the bitangent's side too
        t.x = -t.x;
        t.w = -t.w;
      }
      return t;
    });
  if (!view.texcoords1.empty())
    fill(mesh.add_halfedge_property<Vec2>("h:texcoord1"), [&](Index i) { return view.texcoords1[i]; });
  if (!view.submeshes.empty()) {
    auto submesh = mesh.add_face_property<std::int32_t>(kSubmeshProperty, 0);
    for (std::size_t t = 0; t < rep.face_map.size(); ++t)
      if (rep.face_map[t] != kInvalidIndex) submesh[Face(rep.face_map[t])] = view.submeshes[t];
  }
  return mesh;
}

}  // namespace hedge
