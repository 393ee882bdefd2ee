// glTF 2.0 reading: .gltf (JSON) and .glb (binary container) through tinygltf.
//
// tinygltf parses the JSON, decodes data URIs and GLB chunks; everything it leaves to its user is
// checked here: every index into the file's arrays, every accessor's byte range against its buffer,
// component types per attribute, index ranges and non-finite values.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "gltf_guard.h"
#include "gltf_internal.h"
#include "hedge/core/properties.h"
#include "hedge/io/io.h"
#include "parse_util.h"

namespace hedge {

namespace {

using Mat4 = std::array<double, 16>;  // column-major, as glTF stores node matrices

constexpr Mat4 kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a[k * 4 + row] * b[c * 4 + k];
      r[c * 4 + row] = s;
    }
  return r;
}

// --- tinygltf's callbacks ---------------------------------------------------------------------

bool refuse_write(std::string* err, const std::string& path, const std::vector<unsigned char>&, void*) {
  if (err) *err += "hedge does not write files through tinygltf: " + path + "\n";
  return false;
}

// Images are not needed for the mesh: accepted and left undecoded.
bool skip_image(tg::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
                void*) {
  return true;
}

// tinygltf's messages end in a newline and may hold several lines (and quote a whole uri): one
// line of at most 300 characters for an IoError.
std::string one_line(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ';';
  if (s.size() > 300) s = s.substr(0, 300) + "...";
  return s;
}

// --- reading -------------------------------------------------------------------------------------

std::string str(std::uint64_t v) { return std::to_string(v); }

// One triangle primitive of one node's mesh, decoded and transformed.
struct Primitive {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;    // empty when absent
  std::vector<Vec2> texcoords;  // empty when absent
  std::vector<Color> colors;    // empty when absent
  std::vector<std::uint32_t> triangles;
  int material = -1;  // the primitive's material, -1 for none
  // The earlier primitive whose vertices this one indexes (same node, same attribute accessors),
  // -1 when it has its own; a sharing primitive leaves its vertex arrays empty.
  std::ptrdiff_t shares = -1;
};

class Reader {
 public:
  //! `spent`: the part of the read budget that parsing the JSON took already.
  Reader(const tg::Model& model, const std::string& name, std::size_t file_size, std::uint64_t budget,
         std::uint64_t spent)
      : model_(model), name_(name), file_size_(file_size), budget_(budget), spent_(spent) {}

  IndexedMesh read() {
    // Data under a required extension (Draco, quantization...) cannot be read without it.
    for (const std::string& ext : model_.extensionsRequired)
      fail("requires extension " + ext + ", which hedge does not read");
    if (!model_.scenes.empty()) {
      const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      if (scene >= static_cast<int>(model_.scenes.size()))
        fail("scene " + std::to_string(scene) + " does not exist (the file has " + str(model_.scenes.size()) +
             ")");
      std::vector<char> seen(model_.nodes.size(), 0);
      for (const int node : model_.scenes[static_cast<std::size_t>(scene)].nodes)
        visit(node, seen, "scene " + std::to_string(scene));
    } else {
      for (std::size_t m = 0; m < model_.meshes.size(); ++m)
        place(static_cast<int>(m), kIdentity, "the file");
    }
    check_budget();
    for (const Placement& p : placements_) add_mesh(p.mesh, p.world);
    return assemble();
  }

 private:
  [[noreturn]] void fail(const std::string& message) const { throw IoError(name_, 0, -1, message); }

  // Places the meshes of the tree under `root`, depth first with an explicit stack (a deep
  // hierarchy cannot exhaust the call stack). glTF nodes form disjoint trees: a node reached twice
  // (a second parent, a cycle) is refused, which also bounds the walk by the node count.
  void visit(int root, std::vector<char>& seen, const std::string& from) {
    struct Step {
      int node;
      Mat4 world;
      std::size_t next_child;
    };
    std::vector<Step> stack;
    auto enter = [&](int node, const Mat4& parent, const std::string& by) {
      if (node < 0 || node >= static_cast<int>(model_.nodes.size()))
        fail(by + ": node " + std::to_string(node) + " does not exist (the file has " +
             str(model_.nodes.size()) + ")");
      const auto ni = static_cast<std::size_t>(node);
      if (seen[ni])
        fail(by + ": node " + std::to_string(node) + " is reached a second time (glTF nodes form trees)");
      seen[ni] = 1;
      const tg::Node& n = model_.nodes[ni];
      const Mat4 world = multiply(parent, local_matrix(n, node));
      if (n.mesh != -1) place(n.mesh, world, "node " + std::to_string(node));
      stack.push_back({node, world, 0});
    };
    enter(root, kIdentity, from);
    while (!stack.empty()) {
      Step& top = stack.back();
      const tg::Node& n = model_.nodes[static_cast<std::size_t>(top.node)];
      if (top.next_child == n.children.size()) {
        stack.pop_back();
        continue;
      }
      const int child = n.children[top.next_child++];
      const Mat4 world = top.world;  // `top` dangles once enter() grows the stack
      enter(child, world, "node " + std::to_string(top.node));
    }
  }

  Mat4 local_matrix(const tg::Node& n, int node) const {
    const std::string where = "node " + std::to_string(node) + ": ";
    Mat4 m = kIdentity;
    if (!n.matrix.empty()) {
      if (n.matrix.size() != 16) fail(where + "matrix has " + str(n.matrix.size()) + " numbers, expected 16");
      for (int i = 0; i < 16; ++i) m[static_cast<std::size_t>(i)] = n.matrix[static_cast<std::size_t>(i)];
    } else {
      if (!n.scale.empty() && n.scale.size() != 3) fail(where + "scale needs 3 numbers");
      if (!n.rotation.empty() && n.rotation.size() != 4) fail(where + "rotation needs 4 numbers");
      if (!n.translation.empty() && n.translation.size() != 3) fail(where + "translation needs 3 numbers");
      const double sx = n.scale.empty() ? 1 : n.scale[0], sy = n.scale.empty() ? 1 : n.scale[1],
                   sz = n.scale.empty() ? 1 : n.scale[2];
      double x = 0, y = 0, z = 0, w = 1;
      if (!n.rotation.empty()) {
        x = n.rotation[0], y = n.rotation[1], z = n.rotation[2], w = n.rotation[3];
      }
      // Rotation matrix of the unit quaternion (x, y, z, w), columns scaled, then translated.
      const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),
                           2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                           2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y)};
      const double s[3] = {sx, sy, sz};
      for (int c = 0; c < 3; ++c)
        for (int row = 0; row < 3; ++row) m[static_cast<std::size_t>(c * 4 + row)] = r[c * 3 + row] * s[c];
      if (!n.translation.empty())
        for (int row = 0; row < 3; ++row)
          m[static_cast<std::size_t>(12 + row)] = n.translation[static_cast<std::size_t>(row)];
    }
    for (const double v : m)
      if (!std::isfinite(v)) fail(where + "transform is not finite");
    return m;
  }

  // A mesh placed by a node (or by a file without scenes), read once the whole file's cost is known.
  struct Placement {
    int mesh;
    Mat4 world;
  };

  void place(int mesh, const Mat4& world, const std::string& from) {
    if (mesh < 0 || mesh >= static_cast<int>(model_.meshes.size()))
      fail(from + ": mesh " + std::to_string(mesh) + " does not exist (the file has " +
           str(model_.meshes.size()) + ")");
    placements_.push_back({mesh, world});
  }

  // What decoding and merging a primitive allocates at most, from its accessors' counts alone:
  // decoding holds 8 bytes per component, the primitive and the merged mesh 4 each; a corner costs
  // its index (decoded, in sequence, as a triangle corner) and one index per attribute.
  double primitive_cost(const tg::Primitive& prim) const {
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode < TINYGLTF_MODE_TRIANGLES) return 0;
    auto accessor_count = [&](int index, int* components) -> double {
      if (index < 0 || index >= static_cast<int>(model_.accessors.size())) return 0;
      const tg::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
      const int n = tg::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
      *components = n >= 1 && n <= 4 ? n : 4;
      return static_cast<double>(a.count);
    };
    double cost = 0, vertices = 0;
    int attributes = 0;
    for (const auto& [semantic, index] : prim.attributes) {
      if (semantic != "POSITION" && semantic != "NORMAL" && semantic != "TEXCOORD_0" && semantic != "COLOR_0")
        continue;
      int n = 0;
      const double count = accessor_count(index, &n);
      if (semantic == "POSITION") vertices = count;
      cost += count * n * (8 + 2 * 4);
      ++attributes;
    }
    double sequence = vertices;
    if (prim.indices >= 0) {
      int n = 0;
      sequence = accessor_count(prim.indices, &n);
      cost += sequence * (8 + 4);
    }
    const double corners = mode == TINYGLTF_MODE_TRIANGLES ? sequence : 3 * sequence;
    return cost + corners * (4 + 4 + 4 * attributes);
  }

  // The one budget for everything the file makes, checked before any primitive is decoded.
  void check_budget() const {
    double cost = static_cast<double>(spent_);
    for (const Placement& p : placements_) {
      cost += sizeof(Placement);
      for (const tg::Primitive& prim : model_.meshes[static_cast<std::size_t>(p.mesh)].primitives)
        cost += sizeof(Primitive) + primitive_cost(prim);
    }
    if (cost > static_cast<double>(budget_))
      throw IoError(name_, 0, -1,
                    detail::over_budget("its JSON and the meshes its nodes place", cost, budget_));
  }

  void add_mesh(int mesh, const Mat4& world) {
    vertex_sets_.clear();  // a node's transform applies to its own copy of the vertices
    const tg::Mesh& m = model_.meshes[static_cast<std::size_t>(mesh)];
    for (std::size_t p = 0; p < m.primitives.size(); ++p)
      add_primitive(m.primitives[p], world, "mesh " + std::to_string(mesh) + " primitive " + str(p));
  }

  // The accessor's elements, `components` numbers each, sparse substitution applied and normalized
  // integers mapped to [0, 1] or [-1, 1].
  std::vector<double> decode(int index, const std::string& where, int* components) const {
    if (index < 0 || index >= static_cast<int>(model_.accessors.size()))
      fail(where + ": accessor " + std::to_string(index) + " does not exist (the file has " +
           str(model_.accessors.size()) + ")");
    const std::string at = "accessor " + std::to_string(index) + ": ";
    const tg::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    const int n = tg::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    const int size = tg::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    if (n < 1 || n > 4) fail(at + "type " + std::to_string(a.type) + " is not SCALAR or VEC2..4");
    if (size < 1 || size > 4)
      fail(at + "componentType " + std::to_string(a.componentType) + " is not a glTF component type");
    *components = n;
    const std::size_t elem = static_cast<std::size_t>(n) * static_cast<std::size_t>(size);
    if (a.bufferView < 0 && !a.sparse.isSparse) fail(at + "has neither a bufferView nor sparse values");
    // Without a bufferView the elements are zeros: the count must be one the file can justify.
    if (a.bufferView < 0 && a.count > file_size_)
      fail(at + "count " + str(a.count) + " of zeros is more than the file's size justifies");

    std::vector<double> out;
    if (a.bufferView >= 0) {
      std::size_t stride = 0;
      const unsigned char* p = view_bytes(a.bufferView, a.byteOffset, a.count, elem, true, at, &stride);
      out.resize(a.count * static_cast<std::size_t>(n));
      for (std::size_t i = 0; i < a.count; ++i)
        for (int c = 0; c < n; ++c)
          out[i * static_cast<std::size_t>(n) + static_cast<std::size_t>(c)] =
              component(p + i * stride + static_cast<std::size_t>(c * size), a.componentType, a.normalized);
    } else {
      out.assign(a.count * static_cast<std::size_t>(n), 0.0);
    }

    if (a.sparse.isSparse) {
      const auto& sp = a.sparse;
      if (sp.count < 1 || static_cast<std::size_t>(sp.count) > a.count)
        fail(at + "sparse count " + std::to_string(sp.count) + " is not in [1, " + str(a.count) + "]");
      const int isize = tg::GetComponentSizeInBytes(static_cast<std::uint32_t>(sp.indices.componentType));
      if (sp.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
          sp.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
          sp.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(at + "sparse indices must be unsigned integers");
      const auto count = static_cast<std::size_t>(sp.count);
      std::size_t unused = 0;
      const unsigned char* ip =
          view_bytes(sp.indices.bufferView, static_cast<std::size_t>(sp.indices.byteOffset), count,
                     static_cast<std::size_t>(isize), false, at + "sparse indices: ", &unused);
      const unsigned char* vp =
          view_bytes(sp.values.bufferView, static_cast<std::size_t>(sp.values.byteOffset), count, elem, false,
                     at + "sparse values: ", &unused);
      for (std::size_t k = 0; k < count; ++k) {
        const double target =
            component(ip + k * static_cast<std::size_t>(isize), sp.indices.componentType, false);
        if (target >= static_cast<double>(a.count))
          fail(at + "sparse index " + str(static_cast<std::uint64_t>(target)) + " (entry " + str(k) +
               ") is out of range (count " + str(a.count) + ")");
        const auto e = static_cast<std::size_t>(target);
        for (int c = 0; c < n; ++c)
          out[e * static_cast<std::size_t>(n) + static_cast<std::size_t>(c)] =
              component(vp + k * elem + static_cast<std::size_t>(c * size), a.componentType, a.normalized);
      }
    }
    for (std::size_t i = 0; i < out.size(); ++i)
      if (!std::isfinite(out[i]))
        fail(at + "element " + str(i / static_cast<std::size_t>(n)) + " is not finite");
    return out;
  }

  // Checks that `count` elements of `elem` bytes at `offset` in buffer view `view` lie inside the
  // view and its buffer, and returns the first one. `strided` allows the view's byteStride.
  const unsigned char* view_bytes(int view, std::size_t offset, std::size_t count, std::size_t elem,
                                  bool strided, const std::string& at, std::size_t* stride) const {
    if (view < 0 || view >= static_cast<int>(model_.bufferViews.size()))
      fail(at + "bufferView " + std::to_string(view) + " does not exist (the file has " +
           str(model_.bufferViews.size()) + ")");
    const tg::BufferView& v = model_.bufferViews[static_cast<std::size_t>(view)];
    const std::string vat = at + "bufferView " + std::to_string(view) + ": ";
    if (v.buffer < 0 || v.buffer >= static_cast<int>(model_.buffers.size()))
      fail(vat + "buffer " + std::to_string(v.buffer) + " does not exist (the file has " +
           str(model_.buffers.size()) + ")");
    const std::size_t buffer_size = model_.buffers[static_cast<std::size_t>(v.buffer)].data.size();
    if (v.byteOffset > buffer_size || v.byteLength > buffer_size - v.byteOffset)
      fail(vat + "bytes [" + str(v.byteOffset) + ", " + str(v.byteOffset) + " + " + str(v.byteLength) +
           ") are outside buffer " + std::to_string(v.buffer) + " (" + str(buffer_size) + " bytes)");
    *stride = elem;
    if (strided && v.byteStride != 0) {
      if (v.byteStride < elem)
        fail(vat + "byteStride " + str(v.byteStride) + " is smaller than an element (" + str(elem) +
             " bytes)");
      *stride = v.byteStride;
    }
    if (count == 0) return nullptr;
    if (offset > v.byteLength || elem > v.byteLength - offset ||
        (count - 1) > (v.byteLength - offset - elem) / *stride)
      fail(at + str(count) + " elements of " + str(elem) + " bytes (stride " + str(*stride) + ") from byte " +
           str(offset) + " do not fit in bufferView " + std::to_string(view) + " (" + str(v.byteLength) +
           " bytes)");
    return model_.buffers[static_cast<std::size_t>(v.buffer)].data.data() + v.byteOffset + offset;
  }

  static double component(const unsigned char* p, int type, bool normalized) {
    switch (type) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p, 4);
        return f;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? p[0] / 255.0 : p[0];
      case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const auto v = static_cast<std::int8_t>(p[0]);
        return normalized ? std::max(v / 127.0, -1.0) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? v / 65535.0 : v;
      }
      case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
      }
      default:
        return 0;  // refused by decode() before any element is read
    }
  }

  // An attribute's accessor, checked against what glTF allows for it.
  // `alt_components`, when not 0, is a second component count allowed (COLOR_0: VEC3 or VEC4);
  // `found`, when given, receives the accessor's count.
  std::vector<double> attribute(const tg::Primitive& prim, const char* semantic, int components,
                                bool integers, const std::string& where, int alt_components = 0,
                                int* found = nullptr) const {
    const int index = prim.attributes.at(semantic);
    int n = 0;
    std::vector<double> values = decode(index, where + " " + semantic, &n);
    const tg::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    const std::string at = where + " " + semantic + ": accessor " + std::to_string(index) + ": ";
    if (n != components && (alt_components == 0 || n != alt_components))
      fail(at + "has " + std::to_string(n) + " components, expected " + std::to_string(components) +
           (alt_components ? " or " + std::to_string(alt_components) : std::string()));
    if (found) *found = n;
    const bool is_float = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const bool is_unorm = a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                           a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    if (!is_float && !(integers && is_unorm))
      fail(at + "componentType " + std::to_string(a.componentType) +
           (integers ? " is not FLOAT or a normalized unsigned byte or short" : " is not FLOAT"));
    return values;
  }

  // The attribute accessors a primitive's vertices come from.
  static std::array<int, 4> vertex_accessors(const tg::Primitive& prim) {
    std::array<int, 4> ids{};
    const char* names[4] = {"POSITION", "NORMAL", "TEXCOORD_0", "COLOR_0"};
    for (std::size_t k = 0; k < 4; ++k) {
      const auto it = prim.attributes.find(names[k]);
      ids[k] = it == prim.attributes.end() ? -1 : it->second;
    }
    return ids;
  }

  // Decodes the primitive's vertex attributes into `out`, or, when an earlier primitive of the same
  // node has the same attribute accessors (several materials over one vertex set, as hedge writes
  // submeshes), points `out` at that primitive's vertices. Returns the vertex count.
  std::size_t read_vertices(const tg::Primitive& prim, const std::string& where, Primitive& out) {
    const std::array<int, 4> ids = vertex_accessors(prim);
    const auto [it, added] = vertex_sets_.try_emplace(ids, primitives_.size());
    if (!added) {
      out.shares = static_cast<std::ptrdiff_t>(it->second);
      return primitives_[it->second].positions.size();
    }
    const std::vector<double> pos = attribute(prim, "POSITION", 3, false, where);
    const std::size_t vertices = pos.size() / 3;
    out.positions.resize(vertices);
    for (std::size_t i = 0; i < vertices; ++i)
      out.positions[i] = {static_cast<float>(pos[3 * i]), static_cast<float>(pos[3 * i + 1]),
                          static_cast<float>(pos[3 * i + 2])};
    auto same_count = [&](const char* semantic, std::size_t count) {
      if (count != vertices)
        fail(where + " " + semantic + ": accessor " + std::to_string(prim.attributes.at(semantic)) +
             ": count " + str(count) + " differs from POSITION's " + str(vertices));
    };
    if (prim.attributes.count("NORMAL")) {
      const std::vector<double> nor = attribute(prim, "NORMAL", 3, false, where);
      same_count("NORMAL", nor.size() / 3);
      out.normals.resize(vertices);
      for (std::size_t i = 0; i < vertices; ++i)
        out.normals[i] = {static_cast<float>(nor[3 * i]), static_cast<float>(nor[3 * i + 1]),
                          static_cast<float>(nor[3 * i + 2])};
    }
    if (prim.attributes.count("TEXCOORD_0")) {
      const std::vector<double> uv = attribute(prim, "TEXCOORD_0", 2, true, where);
      same_count("TEXCOORD_0", uv.size() / 2);
      out.texcoords.resize(vertices);
      // glTF's texture origin is the top left corner, hedge's (OBJ's) the bottom left one.
      for (std::size_t i = 0; i < vertices; ++i)
        out.texcoords[i] = {static_cast<float>(uv[2 * i]), 1.0f - static_cast<float>(uv[2 * i + 1])};
    }
    if (prim.attributes.count("COLOR_0")) {
      int n = 0;
      const std::vector<double> col = attribute(prim, "COLOR_0", 4, true, where, 3, &n);
      const auto k = static_cast<std::size_t>(n);
      same_count("COLOR_0", col.size() / k);
      out.colors.resize(vertices);
      // RGB colours are opaque.
      for (std::size_t i = 0; i < vertices; ++i)
        out.colors[i] = {static_cast<float>(col[k * i]), static_cast<float>(col[k * i + 1]),
                         static_cast<float>(col[k * i + 2]),
                         k == 4 ? static_cast<float>(col[k * i + 3]) : 1.0f};
    }

    return vertices;
  }

  void add_primitive(const tg::Primitive& prim, const Mat4& world, const std::string& where) {
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP) {
      static constexpr const char* kNames[] = {"points", "lines", "line loop", "line strip"};
      warnings_.push_back({name_, 0, -1,
                           where + ": mode " + std::to_string(mode) + " (" + kNames[mode] +
                               ") is not a surface and is not read"});
      return;
    }
    if (mode > TINYGLTF_MODE_TRIANGLE_FAN)
      fail(where + ": mode " + std::to_string(mode) + " is not a glTF mode");
    if (prim.attributes.find("POSITION") == prim.attributes.end())
      fail(where + ": has no POSITION attribute");

    if (prim.material >= 0 && static_cast<std::size_t>(prim.material) >= model_.materials.size())
      fail(where + ": material " + std::to_string(prim.material) + " does not exist (the file has " +
           str(model_.materials.size()) + ")");
    Primitive out;
    out.material = prim.material;
    const std::size_t vertices = read_vertices(prim, where, out);
    // The primitive's vertex sequence, then its triangles.
    std::vector<std::uint32_t> seq;
    if (prim.indices >= 0) {
      int n = 0;
      const std::string iwhere = where + " indices";
      const std::vector<double> idx = decode(prim.indices, iwhere, &n);
      const tg::Accessor& a = model_.accessors[static_cast<std::size_t>(prim.indices)];
      const std::string at = iwhere + ": accessor " + std::to_string(prim.indices) + ": ";
      if (n != 1) fail(at + "indices must be SCALAR");
      if (a.normalized || (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                           a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                           a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        fail(at + "indices must be unsigned bytes, shorts or ints, not normalized");
      seq.resize(idx.size());
      for (std::size_t i = 0; i < idx.size(); ++i) {
        if (idx[i] >= static_cast<double>(vertices))
          fail(at + "index " + str(static_cast<std::uint64_t>(idx[i])) + " (element " + str(i) +
               ") is out of range (POSITION has " + str(vertices) + " vertices)");
        seq[i] = static_cast<std::uint32_t>(idx[i]);
      }
    } else {
      if (vertices > std::numeric_limits<std::uint32_t>::max()) fail(where + ": too many vertices");
      seq.resize(vertices);
      for (std::size_t i = 0; i < vertices; ++i) seq[i] = static_cast<std::uint32_t>(i);
    }
    auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, bool drop_degenerate) {
      if (drop_degenerate && (a == b || b == c || a == c)) return;
      out.triangles.insert(out.triangles.end(), {a, b, c});
    };
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      if (seq.size() % 3 != 0)
        fail(where + ": " + str(seq.size()) + (prim.indices >= 0 ? " indices" : " vertices") +
             " is not a multiple of 3 (mode TRIANGLES)");
      for (std::size_t i = 0; i < seq.size(); i += 3) emit(seq[i], seq[i + 1], seq[i + 2], false);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      // Every other triangle is flipped to keep one orientation; repeated indices stitch strips.
      for (std::size_t i = 0; i + 2 < seq.size(); ++i)
        if (i % 2 == 0)
          emit(seq[i], seq[i + 1], seq[i + 2], true);
        else
          emit(seq[i], seq[i + 2], seq[i + 1], true);
    } else {
      for (std::size_t i = 1; i + 1 < seq.size(); ++i) emit(seq[i], seq[i + 1], seq[0], true);
    }

    if (out.shares < 0) transform(out, world);
    // A mirroring transform turns counter-clockwise triangles clockwise: reverse them back.
    if (world != kIdentity && mirrors(world))
      for (std::size_t t = 0; t + 2 < out.triangles.size(); t += 3)
        std::swap(out.triangles[t + 1], out.triangles[t + 2]);
    primitives_.push_back(std::move(out));
  }

  // Applies a node's world matrix to the vertices. The identity leaves every value as it is, bit
  // for bit.
  void transform(Primitive& p, const Mat4& m) const {
    if (m == kIdentity) return;
    for (Vec3& v : p.positions) {
      const double x = v.x, y = v.y, z = v.z;
      v = {static_cast<float>(m[0] * x + m[4] * y + m[8] * z + m[12]),
           static_cast<float>(m[1] * x + m[5] * y + m[9] * z + m[13]),
           static_cast<float>(m[2] * x + m[6] * y + m[10] * z + m[14])};
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        fail("a node's transform takes a position out of float range");
    }
    // Normals go through the cofactor matrix (the inverse transpose times the determinant).
    const double a = m[0], b = m[4], c = m[8], d = m[1], e = m[5], f = m[9], g = m[2], h = m[6], i = m[10];
    const double cof[9] = {e * i - f * h,    -(d * i - f * g), d * h - e * g,     // row 0
                           -(b * i - c * h), a * i - c * g,    -(a * h - b * g),  // row 1
                           b * f - c * e,    -(a * f - c * d), a * e - b * d};    // row 2
    const double det = a * cof[0] + b * cof[1] + c * cof[2];
    const double sign = det < 0 ? -1.0 : 1.0;
    for (Vec3& n : p.normals) {
      const double x = n.x, y = n.y, z = n.z;
      double r[3];
      for (int row = 0; row < 3; ++row)
        r[row] = sign * (cof[row * 3] * x + cof[row * 3 + 1] * y + cof[row * 3 + 2] * z);
      const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
      n = len > 0 ? Vec3{static_cast<float>(r[0] / len), static_cast<float>(r[1] / len),
                         static_cast<float>(r[2] / len)}
                  : Vec3{0, 0, 0};
    }
  }

  // Whether the transform's linear part has a negative determinant.
  static bool mirrors(const Mat4& m) {
    const double det = m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
                       m[8] * (m[1] * m[6] - m[5] * m[2]);
    return det < 0;
  }

  IndexedMesh assemble() {
    IndexedMesh mesh;
    bool normals = !primitives_.empty(), texcoords = !primitives_.empty(), colors = !primitives_.empty();
    bool materials = false;
    std::size_t vertices = 0, corners = 0;
    for (const Primitive& p : primitives_) {
      const Primitive& v = p.shares < 0 ? p : primitives_[static_cast<std::size_t>(p.shares)];
      normals = normals && !v.normals.empty();
      texcoords = texcoords && !v.texcoords.empty();
      colors = colors && !v.colors.empty();
      materials = materials || p.material >= 0;
      vertices += p.positions.size();
      corners += p.triangles.size();
    }
    if (vertices > std::numeric_limits<std::uint32_t>::max()) fail("more than 2^32 - 1 vertices in all");
    mesh.positions.reserve(vertices);
    mesh.indices.reserve(corners);
    std::vector<std::uint32_t> bases(primitives_.size());
    for (std::size_t q = 0; q < primitives_.size(); ++q) {
      const Primitive& p = primitives_[q];
      bases[q] = p.shares < 0 ? static_cast<std::uint32_t>(mesh.positions.size())
                              : bases[static_cast<std::size_t>(p.shares)];
      mesh.positions.insert(mesh.positions.end(), p.positions.begin(), p.positions.end());
      if (normals) mesh.normals.insert(mesh.normals.end(), p.normals.begin(), p.normals.end());
      if (texcoords) mesh.texcoords.insert(mesh.texcoords.end(), p.texcoords.begin(), p.texcoords.end());
      if (colors) mesh.colors.insert(mesh.colors.end(), p.colors.begin(), p.colors.end());
      for (const std::uint32_t i : p.triangles) mesh.indices.push_back(bases[q] + i);
      // A primitive's material is its faces' submesh (0 without one), as write_gltf() writes them.
      if (materials)
        mesh.face_submeshes.insert(mesh.face_submeshes.end(), p.triangles.size() / 3,
                                   p.material >= 0 ? std::min(p.material, kMaxSubmesh) : 0);
    }
    // glTF attributes are per vertex: the corner index is the vertex index.
    if (normals) mesh.normal_indices = mesh.indices;
    if (texcoords) mesh.texcoord_indices = mesh.indices;
    if (colors) mesh.color_indices = mesh.indices;
    mesh.warnings = std::move(warnings_);
    return mesh;
  }

  const tg::Model& model_;
  const std::string& name_;
  std::size_t file_size_;
  std::uint64_t budget_, spent_;
  std::vector<Placement> placements_;
  std::vector<Primitive> primitives_;
  // The attribute accessors of the placed mesh's vertex sets, each with the primitive that read it.
  std::map<std::array<int, 4>, std::size_t> vertex_sets_;
  std::vector<ReadWarning> warnings_;
};

}  // namespace

IndexedMesh read_gltf(std::string_view data, const std::string& name, const ReadOptions& options) {
  if (data.size() > std::numeric_limits<std::uint32_t>::max())
    throw IoError(name, 0, -1, "file too large for glTF (4 GiB or more)");
  // Nothing reaches tinygltf before the guard has scanned the JSON and approved the buffer files.
  const detail::GltfScan scan = detail::scan_gltf(data, name);
  detail::GltfBufferFiles files(scan, name, options);
  const std::uint64_t budget = read_budget(options, data.size() + files.bytes());
  if (static_cast<double>(scan.parse_cost) > static_cast<double>(budget))
    throw IoError(name, 0, -1, detail::over_budget("its JSON", static_cast<double>(scan.parse_cost), budget));

  tg::TinyGLTF loader;
  loader.SetImageLoader(&skip_image, nullptr);
  loader.SetFsCallbacks({&detail::GltfBufferFiles::exists, &detail::GltfBufferFiles::expand,
                         &detail::GltfBufferFiles::read, &refuse_write, &files});
  tg::Model model;
  std::string err, warn;
  bool ok = false;
  try {
    if (scan.binary)
      ok = loader.LoadBinaryFromMemory(&model, &err, &warn,
                                       reinterpret_cast<const unsigned char*>(data.data()),
                                       static_cast<unsigned int>(data.size()), files.base_dir());
    else
      ok = loader.LoadASCIIFromString(&model, &err, &warn, data.data(),
                                      static_cast<unsigned int>(data.size()), files.base_dir());
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw IoError(name, 0, -1, std::string("malformed glTF: ") + e.what());
  }
  if (!ok) {
    const std::string why = one_line(err.empty() ? warn : err);
    throw IoError(name, 0, -1,
                  std::string(scan.binary ? "malformed glTF binary: " : "malformed glTF: ") +
                      (why.empty() ? "rejected by the parser" : why));
  }
  return Reader(model, name, data.size(), budget, scan.parse_cost).read();
}

}  // namespace hedge
