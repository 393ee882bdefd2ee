// glTF 2.0 writing: .gltf (JSON with the buffer as a data URI) and .glb (binary container), one
// triangle primitive per submesh, through tinygltf's serializer.

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "gltf_internal.h"
#include "hedge/core/properties.h"
#include "hedge/io/io.h"
#include "parse_util.h"

namespace hedge {

namespace {

struct CornerKey {
  std::uint32_t v, t, n, c;
  friend bool operator==(const CornerKey&, const CornerKey&) = default;
};

struct CornerKeyHash {
  std::size_t operator()(const CornerKey& k) const noexcept {
    std::uint64_t h = k.v * 0x9E3779B97F4A7C15ull;
    h ^= (k.t + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2));
    h ^= (k.n * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2));
    h ^= (k.c * 0x165667B19E3779F9ull + (h << 6) + (h >> 2));
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

template <typename T>
void append_pod(std::vector<unsigned char>& out, const T& v) {
  const auto* p = reinterpret_cast<const unsigned char*>(&v);
  out.insert(out.end(), p, p + sizeof(T));
}

//! Triangles, polygons fanned from their first corner, as corner numbers into mesh.indices, and
//! the submesh of each triangle (its face's) when the mesh has face_submeshes.
struct FannedTriangles {
  std::vector<std::size_t> corners;
  std::vector<std::int32_t> submeshes;
};

FannedTriangles fan_corners(const IndexedMesh& mesh) {
  FannedTriangles out;
  out.corners.reserve(mesh.indices.size());
  const bool submeshes = !mesh.face_submeshes.empty();
  std::size_t face = 0;
  detail::for_each_face(mesh, [&](std::size_t first, std::size_t n) {
    for (std::size_t k = 1; k + 1 < n; ++k) {
      out.corners.insert(out.corners.end(), {first, first + k, first + k + 1});
      if (submeshes) out.submeshes.push_back(mesh.face_submeshes[face]);
    }
    ++face;
  });
  return out;
}

//! Refuses face_submeshes that are not one per face in [0, kMaxSubmesh], naming the first wrong one.
void check_submeshes(const IndexedMesh& mesh) {
  if (mesh.face_submeshes.empty()) return;
  if (mesh.face_submeshes.size() != mesh.face_count())
    throw InvalidInputError("indexed mesh: " + std::to_string(mesh.face_submeshes.size()) +
                            " face submeshes for " + std::to_string(mesh.face_count()) + " faces");
  for (std::size_t f = 0; f < mesh.face_submeshes.size(); ++f)
    if (mesh.face_submeshes[f] < 0 || mesh.face_submeshes[f] > kMaxSubmesh)
      throw InvalidInputError("indexed mesh: face " + std::to_string(f) + " has submesh " +
                              std::to_string(mesh.face_submeshes[f]) + ", outside [0, " +
                              std::to_string(kMaxSubmesh) + "]");
}

//! glTF's vertices, each a distinct (position, texcoord, normal, colour) of a corner, and the
//! triangles' indices into them.
struct GltfVertices {
  std::vector<CornerKey> keys;
  std::vector<std::uint32_t> indices;
};

//! Vertex v of the mesh keeps number v with the attributes of its first corner, so positions come
//! back in their order; corners that differ from it (seams, hard edges) get vertices after the
//! mesh's own. A vertex no corner uses keeps its position with out-of-range attribute indices: zeros.
GltfVertices split_at_seams(const IndexedMesh& mesh, const std::vector<std::size_t>& corners) {
  const bool has_t = !mesh.texcoord_indices.empty();
  const bool has_n = !mesh.normal_indices.empty();
  const bool has_c = !mesh.color_indices.empty();
  const std::size_t nv = mesh.positions.size();
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  GltfVertices out;
  std::vector<CornerKey>& keys = out.keys;
  keys.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) keys[v] = {static_cast<std::uint32_t>(v), kNone, kNone, kNone};
  std::vector<char> keyed(nv, 0);
  std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> extra;
  out.indices.reserve(corners.size());
  for (const std::size_t c : corners) {
    const CornerKey key{mesh.indices[c], has_t ? mesh.texcoord_indices[c] : 0,
                        has_n ? mesh.normal_indices[c] : 0, has_c ? mesh.color_indices[c] : 0};
    if (!keyed[key.v]) {
      keyed[key.v] = 1;
      keys[key.v] = key;
    }
    if (keys[key.v] == key) {
      out.indices.push_back(key.v);
      continue;
    }
    const auto [it, added] = extra.try_emplace(key, 0);
    if (added) {
      if (keys.size() >= std::numeric_limits<std::uint32_t>::max() - 1)
        throw InvalidInputError("too many vertices for glTF indices once split at seams");
      it->second = static_cast<std::uint32_t>(keys.size());
      keys.push_back(key);
    }
    out.indices.push_back(it->second);
  }
  return out;
}

//! The model's one buffer, filled view by view, with an accessor per view.
class BufferWriter {
 public:
  explicit BufferWriter(tg::Model& model) : model_(model) {}

  std::vector<unsigned char>& bytes() { return buffer_.data; }

  //! An accessor of `n` elements over the bytes appended since `begin`, in a view of its own.
  int add_accessor(std::size_t begin, int target, int component_type, int type, std::size_t n) {
    std::vector<unsigned char>& bytes = buffer_.data;
    tg::BufferView view;
    view.buffer = 0;
    view.byteOffset = begin;
    view.byteLength = bytes.size() - begin;
    view.target = target;
    model_.bufferViews.push_back(view);
    while (bytes.size() % 4 != 0) bytes.push_back(0);  // every view starts 4-byte aligned
    tg::Accessor a;
    a.bufferView = static_cast<int>(model_.bufferViews.size() - 1);
    a.componentType = component_type;
    a.type = type;
    a.count = n;
    model_.accessors.push_back(a);
    return static_cast<int>(model_.accessors.size() - 1);
  }

  //! An attribute of float vectors, `get(key)` giving each vertex's.
  template <typename Get>
  int add_floats(const std::vector<CornerKey>& keys, int type, Get get) {
    const std::size_t begin = buffer_.data.size();
    for (const CornerKey& k : keys)
      for (const float f : get(k)) append_pod(buffer_.data, f);
    return add_accessor(begin, TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT, type,
                        keys.size());
  }

  //! The triangles' indices, 16-bit when they fit; the largest value of a type is reserved
  //! (primitive restart).
  int add_indices(const std::vector<std::uint32_t>& indices, std::size_t vertices) {
    const std::size_t begin = buffer_.data.size();
    const bool shorts = vertices < 0xFFFF;
    for (const std::uint32_t i : indices)
      if (shorts)
        append_pod(buffer_.data, static_cast<std::uint16_t>(i));
      else
        append_pod(buffer_.data, i);
    return add_accessor(
        begin, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER,
        shorts ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
        TINYGLTF_TYPE_SCALAR, indices.size());
  }

  //! Hands the buffer to the model.
  void finish() {
    if (buffer_.data.size() > std::numeric_limits<std::uint32_t>::max() - 1024u)
      throw InvalidInputError("mesh too large for one glTF buffer");
    model_.buffers.push_back(std::move(buffer_));
  }

 private:
  tg::Model& model_;
  tg::Buffer buffer_;
};

//! The primitive's attributes: positions (with their bounds, which glTF requires), then the
//! normals, texture coordinates and colours the mesh has.
void write_attributes(const IndexedMesh& mesh, const std::vector<CornerKey>& keys, BufferWriter& buffer,
                      tg::Model& model, tg::Primitive& prim) {
  Vec3 lo = mesh.positions[keys[0].v], hi = lo;
  prim.attributes["POSITION"] = buffer.add_floats(keys, TINYGLTF_TYPE_VEC3, [&](const CornerKey& k) {
    const Vec3& p = mesh.positions[k.v];
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    return std::array<float, 3>{p.x, p.y, p.z};
  });
  model.accessors.back().minValues = {lo.x, lo.y, lo.z};
  model.accessors.back().maxValues = {hi.x, hi.y, hi.z};
  if (!mesh.normal_indices.empty())
    prim.attributes["NORMAL"] = buffer.add_floats(keys, TINYGLTF_TYPE_VEC3, [&](const CornerKey& k) {
      const Vec3 n = k.n < mesh.normals.size() ? mesh.normals[k.n] : Vec3{0, 0, 0};
      return std::array<float, 3>{n.x, n.y, n.z};
    });
  if (!mesh.texcoord_indices.empty())
    prim.attributes["TEXCOORD_0"] = buffer.add_floats(keys, TINYGLTF_TYPE_VEC2, [&](const CornerKey& k) {
      const Vec2 t = k.t < mesh.texcoords.size() ? mesh.texcoords[k.t] : Vec2{0, 0};
      return std::array<float, 2>{t.x, 1.0f - t.y};  // top-left texture origin
    });
  if (!mesh.color_indices.empty())
    prim.attributes["COLOR_0"] = buffer.add_floats(keys, TINYGLTF_TYPE_VEC4, [&](const CornerKey& k) {
      const Color c = k.c < mesh.colors.size() ? mesh.colors[k.c] : Color{0, 0, 0, 0};
      return std::array<float, 4>{c.r, c.g, c.b, c.a};
    });
}

std::string serialize(tg::Model& model, bool binary, const char* what) {
  std::ostringstream out;
  if (!tg::TinyGLTF().WriteGltfSceneToStream(&model, out, !binary, binary))
    throw InvalidInputError(std::string("glTF: cannot serialize") + what);
  return out.str();
}

//! One primitive per submesh, in increasing submesh order, each drawing its triangles in face
//! order with material number = submesh (materials 0 to the largest submesh, named "submesh_N",
//! so a reader maps a primitive's material straight back to its submesh). All primitives share
//! the vertex accessors: a vertex where two submeshes meet is written once, and the reader, which
//! reads primitives that share accessors as one vertex set, gives the mesh back connected.
std::vector<tg::Primitive> submesh_primitives(const tg::Primitive& shared, const GltfVertices& vertices,
                                              const std::vector<std::int32_t>& submeshes,
                                              BufferWriter& buffer, tg::Model& model) {
  const std::int32_t largest = *std::max_element(submeshes.begin(), submeshes.end());
  std::vector<std::vector<std::uint32_t>> indices(static_cast<std::size_t>(largest) + 1);
  for (std::size_t t = 0; t < submeshes.size(); ++t) {
    std::vector<std::uint32_t>& out = indices[static_cast<std::size_t>(submeshes[t])];
    out.insert(out.end(), vertices.indices.begin() + static_cast<std::ptrdiff_t>(3 * t),
               vertices.indices.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
  }
  std::vector<tg::Primitive> prims;
  for (std::size_t s = 0; s < indices.size(); ++s) {
    tg::Material material;
    material.name = "submesh_" + std::to_string(s);
    model.materials.push_back(std::move(material));
    if (indices[s].empty()) continue;
    tg::Primitive prim = shared;
    prim.indices = buffer.add_indices(indices[s], vertices.keys.size());
    prim.material = static_cast<int>(s);
    prims.push_back(std::move(prim));
  }
  return prims;
}

std::string write_model(const IndexedMesh& mesh, bool binary) {
  detail::check_writable(mesh);
  check_submeshes(mesh);
  const FannedTriangles triangles = fan_corners(mesh);
  const GltfVertices vertices = split_at_seams(mesh, triangles.corners);
  tg::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "hedge";
  // Nothing to draw: a valid file with no scene (glTF accessors cannot be empty).
  if (vertices.indices.empty() || vertices.keys.empty()) return serialize(model, binary, "");

  BufferWriter buffer(model);
  tg::Primitive prim;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  write_attributes(mesh, vertices.keys, buffer, model, prim);
  tg::Mesh m;
  if (triangles.submeshes.empty()) {
    prim.indices = buffer.add_indices(vertices.indices, vertices.keys.size());
    m.primitives.push_back(std::move(prim));
  } else {
    m.primitives = submesh_primitives(prim, vertices, triangles.submeshes, buffer, model);
  }
  buffer.finish();

  // One scene of one node holding the one mesh.
  model.scenes.emplace_back();
  model.defaultScene = 0;
  model.meshes.push_back(std::move(m));
  tg::Node node;
  node.mesh = 0;
  model.nodes.push_back(node);
  model.scenes[0].nodes.push_back(0);
  return serialize(model, binary, " the mesh");
}

}  // namespace

std::string write_gltf(const IndexedMesh& mesh, const WriteOptions&) { return write_model(mesh, false); }

std::string write_glb(const IndexedMesh& mesh, const WriteOptions&) { return write_model(mesh, true); }

}  // namespace hedge
