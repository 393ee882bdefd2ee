// Wavefront OBJ: v / vt / vn / f, with the v, v/vt, v//vn and v/vt/vn corner forms, negative
// (relative) indices, polygons, comments and backslash line continuations. Grouping, material,
// smoothing, line and point statements are ignored; an unknown keyword is an error, because a file
// made of unrecognised lines is far more likely to be the wrong file than a mesh.
//
// Attributes: the texture coordinate (normal) pool and per-corner indices are kept only when every
// corner of every face names one. A file where some corners have vt and others do not gets no
// texture coordinates at all, without an error: a partial attribute cannot be carried per corner.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "hedge/io/io.h"
#include "parse_util.h"

namespace hedge {

namespace {

using detail::at_token_end;
using detail::describe_token;
using detail::is_blank;
using detail::quote;

// Keywords of the OBJ specification (and common extensions) that carry nothing a polygon mesh uses.
constexpr std::string_view kIgnoredKeywords[] = {
    "o",         "g",     "s",     "usemtl", "mtllib",   "l",        "p",      "vp",     "cstype",
    "deg",       "bmat",  "step",  "curv",   "curv2",    "surf",     "parm",   "trim",   "hole",
    "scrv",      "sp",    "end",   "con",    "mg",       "lod",      "usemap", "maplib", "shadow_obj",
    "trace_obj", "ctech", "stech", "bevel",  "c_interp", "d_interp", "call",   "csh"};

bool is_ignored_keyword(std::string_view k) {
  for (auto s : kIgnoredKeywords)
    if (s == k) return true;
  return false;
}

// The largest index a face used before the pool it points into was complete (OBJ lets a face name
// a vertex defined further down); checked once the whole file is read.
struct ForwardRef {
  std::uint64_t index = 0;  // 0-based; meaningful when line != 0
  std::uint64_t line = 0;
  std::uint64_t face = 0;
};

// An index this large is out of range of any pool (they are indexed by 32 bits).
constexpr std::uint64_t kMaxIndex = std::numeric_limits<std::uint32_t>::max();

// The sizes of the pools (vertices, texture coordinates, normals) once the whole file is read;
// kUnchecked for an attribute that is dropped (see the top of the file).
struct PoolSizes {
  static constexpr std::uint64_t kUnchecked = std::numeric_limits<std::uint64_t>::max();
  std::uint64_t positions = kUnchecked, texcoords = kUnchecked, normals = kUnchecked;
};

// Reads the file in one pass. An index past its pool can only be judged at the end (the pool may
// grow further down); when one is, the file is read again knowing the final pool sizes, so that
// the error names the first face that goes out of range, not the one with the largest index.
class ObjReader {
 public:
  ObjReader(std::string_view data, const std::string& name, const PoolSizes* final_sizes = nullptr)
      : data_(data), p_(data.data()), end_(data.data() + data.size()), name_(name), final_(final_sizes) {}

  IndexedMesh read() {
    while (p_ < end_) {
      skip_blanks();
      if (p_ == end_) break;
      const char c = *p_;
      if (c == '\n') {
        ++p_;
        ++line_;
        continue;
      }
      if (c == '#') {
        skip_line();
        continue;
      }
      const char* k = p_;
      while (p_ < end_ && !detail::is_space(*p_)) ++p_;
      const std::string_view keyword(k, static_cast<std::size_t>(p_ - k));
      if (keyword == "v") {
        read_position();
      } else if (keyword == "f") {
        read_face();
      } else if (keyword == "vt") {
        read_texcoord();
      } else if (keyword == "vn") {
        read_normal();
      } else if (is_ignored_keyword(keyword)) {
        skip_line();
      } else {
        fail("unknown keyword " + quote(keyword) + " (expected v, vt, vn, f or a comment)");
      }
    }
    return finish();
  }

 private:
  [[noreturn]] void fail(const std::string& message) const { throw IoError(name_, line_, -1, message); }
  [[noreturn]] void fail_at(std::uint64_t line, const std::string& message) const {
    throw IoError(name_, line, -1, message);
  }

  // Blanks, and backslash-newline continuations, which join two lines into one statement.
  void skip_blanks() {
    for (;;) {
      while (p_ < end_ && is_blank(*p_)) ++p_;
      if (p_ < end_ && *p_ == '\\') {
        const char* q = p_ + 1;
        while (q < end_ && *q == '\r') ++q;
        if (q < end_ && *q == '\n') {
          p_ = q + 1;
          ++line_;
          continue;
        }
      }
      return;
    }
  }

  // Moves past the end of the current statement (following continuations).
  void skip_line() {
    for (;;) {
      const char* start = p_;
      const void* nl = std::memchr(p_, '\n', static_cast<std::size_t>(end_ - p_));
      if (nl == nullptr) {
        p_ = end_;
        return;
      }
      const char* q = static_cast<const char*>(nl);
      const char* b = q;
      while (b > start && b[-1] == '\r') --b;
      const bool continued = b > start && b[-1] == '\\';
      p_ = q + 1;
      ++line_;
      if (!continued) return;
    }
  }

  bool at_statement_end() {
    skip_blanks();
    return p_ == end_ || *p_ == '\n' || *p_ == '#';
  }

  float read_number(std::string_view keyword, int component) {
    skip_blanks();
    float v = 0;
    const char* q = detail::parse_float(p_, end_, v);
    if (q == nullptr || !at_token_end(q, end_)) {
      static constexpr const char* kOrdinal[] = {"first", "second", "third"};
      fail("expected the " + std::string(kOrdinal[component]) + " number after '" + std::string(keyword) +
           "', got " + describe_token(p_, end_));
    }
    p_ = q;
    return v;
  }

  //! The three numbers of a `statement` ("v", "vn").
  Vec3 read_vec3(const char* statement) {
    Vec3 v;
    v.x = read_number(statement, 0);
    v.y = read_number(statement, 1);
    v.z = read_number(statement, 2);
    return v;
  }

  void read_position() {
    const Vec3 v = read_vec3("v");
    if (!is_finite(v))
      fail("vertex " + std::to_string(mesh_.positions.size()) + " has a non-finite coordinate");
    mesh_.positions.push_back(v);
    // A w coordinate or per-vertex colours may follow; neither is kept.
    skip_line();
  }

  void read_texcoord() {
    Vec2 t;
    t.x = read_number("vt", 0);
    // v is optional in the specification (1D textures); it defaults to 0.
    if (!at_statement_end()) t.y = read_number("vt", 1);
    if (!is_finite(t))
      fail("texture coordinate " + std::to_string(mesh_.texcoords.size()) + " has a non-finite component");
    mesh_.texcoords.push_back(t);
    skip_line();
  }

  void read_normal() {
    const Vec3 n = read_vec3("vn");
    if (!is_finite(n)) fail("normal " + std::to_string(mesh_.normals.size()) + " has a non-finite component");
    mesh_.normals.push_back(n);
    skip_line();
  }

  // Resolves a 1-based or negative OBJ index against a pool holding `count` entries so far and
  // `final_count` at the end of the file (kUnchecked in the first pass, where it is not known yet).
  std::uint32_t resolve(std::int64_t raw, std::size_t count, std::uint64_t final_count, ForwardRef& forward,
                        const char* what) {
    const std::uint64_t face = mesh_.face_sizes.size();
    if (raw > 0) {
      const auto index = static_cast<std::uint64_t>(raw - 1);
      if (final_ != nullptr && (index >= final_count || index >= kMaxIndex))
        fail(out_of_range(face, what, index, final_count));
      // An index too large for any pool waits as well, so that errors come in file order.
      if (index >= count && (forward.line == 0 || index > forward.index)) forward = {index, line_, face};
      return static_cast<std::uint32_t>(std::min(index, kMaxIndex));
    }
    if (raw == 0)
      fail("face " + std::to_string(face) + ": " + what + " index 0 is invalid (OBJ indices start at 1)");
    if (static_cast<std::uint64_t>(-(raw + 1)) >= count)
      fail("face " + std::to_string(face) + ": relative " + what + " index " + std::to_string(raw) +
           " refers before the first " + what + " (" + std::to_string(count) + " defined so far)");
    return static_cast<std::uint32_t>(static_cast<std::int64_t>(count) + raw);
  }

  void read_face() {
    std::size_t corners = 0;
    for (;;) {
      if (at_statement_end()) break;
      std::int64_t raw = 0;
      const char* q = detail::parse_int(p_, end_, raw);
      if (q == nullptr) fail("expected a vertex index after 'f', got " + describe_token(p_, end_));
      p_ = q;
      mesh_.indices.push_back(
          resolve(raw, mesh_.positions.size(), final_sizes().positions, forward_v_, "vertex"));
      if (p_ < end_ && *p_ == '/') {
        ++p_;
        if (p_ < end_ && *p_ != '/') {
          q = detail::parse_int(p_, end_, raw);
          if (q == nullptr)
            fail("expected a texture coordinate index after '/', got " + describe_token(p_, end_));
          p_ = q;
          mesh_.texcoord_indices.push_back(resolve(raw, mesh_.texcoords.size(), final_sizes().texcoords,
                                                   forward_vt_, "texture coordinate"));
        }
        if (p_ < end_ && *p_ == '/') {
          ++p_;
          q = detail::parse_int(p_, end_, raw);
          if (q == nullptr) fail("expected a normal index after '/', got " + describe_token(p_, end_));
          p_ = q;
          mesh_.normal_indices.push_back(
              resolve(raw, mesh_.normals.size(), final_sizes().normals, forward_vn_, "normal"));
        }
      }
      if (!at_token_end(p_, end_) && *p_ != '#' && *p_ != '\\')
        fail("unexpected " + quote(std::string_view(p_, 1)) +
             " in a face corner (expected v, v/vt, v//vn or v/vt/vn)");
      ++corners;
    }
    if (corners == 0) fail("expected a vertex index after 'f', got " + describe_token(p_, end_));
    if (corners > std::numeric_limits<std::uint32_t>::max()) fail("face has too many corners");
    if (corners < 3)
      mesh_.warnings.push_back(
          {name_, line_, -1, detail::short_face_message(mesh_.face_sizes.size(), corners)});
    mesh_.face_sizes.push_back(static_cast<std::uint32_t>(corners));
    skip_line();
  }

  static std::string out_of_range(std::uint64_t face, const char* what, std::uint64_t index,
                                  std::uint64_t count) {
    const std::string head =
        "face " + std::to_string(face) + ": " + what + " index " + std::to_string(index + 1);
    if (index >= kMaxIndex) return head + " is too large";
    return head + " is out of range (the file defines " + std::to_string(count) + ")";
  }

  const PoolSizes& final_sizes() const {
    static const PoolSizes kUnknown;
    return final_ != nullptr ? *final_ : kUnknown;
  }

  IndexedMesh finish() {
    // Attributes named by only some corners cannot be expressed per corner: drop them (see top).
    const std::size_t corners = mesh_.indices.size();
    PoolSizes sizes;
    sizes.positions = mesh_.positions.size();
    if (corners != 0 && mesh_.texcoord_indices.size() == corners) sizes.texcoords = mesh_.texcoords.size();
    if (corners != 0 && mesh_.normal_indices.size() == corners) sizes.normals = mesh_.normals.size();
    const struct {
      const ForwardRef& ref;
      std::uint64_t count;
      const char* what;
    } pools[] = {{forward_v_, sizes.positions, "vertex"},
                 {forward_vt_, sizes.texcoords, "texture coordinate"},
                 {forward_vn_, sizes.normals, "normal"}};
    for (const auto& pool : pools) {
      const ForwardRef& f = pool.ref;
      if (f.line == 0 || (f.index < pool.count && f.index < kMaxIndex)) continue;
      // The second reading stops at the first index out of range (see ObjReader); should it not,
      // the largest index is out of range all the same.
      if (final_ == nullptr) {
        mesh_ = IndexedMesh{};  // freed before the second reading allocates its own
        ObjReader(data_, name_, &sizes).read();
      }
      fail_at(f.line, out_of_range(f.face, pool.what, f.index, pool.count));
    }
    if (sizes.texcoords == PoolSizes::kUnchecked) {
      mesh_.texcoords.clear();
      mesh_.texcoord_indices.clear();
    }
    if (sizes.normals == PoolSizes::kUnchecked) {
      mesh_.normals.clear();
      mesh_.normal_indices.clear();
    }
    detail::compact_face_sizes(mesh_);
    return std::move(mesh_);
  }

  std::string_view data_;
  const char* p_;
  const char* end_;
  const std::string& name_;
  std::uint64_t line_ = 1;
  IndexedMesh mesh_;
  const PoolSizes* final_;
  ForwardRef forward_v_, forward_vt_, forward_vn_;
};

}  // namespace

IndexedMesh read_obj(std::string_view data, const std::string& name) { return ObjReader(data, name).read(); }

std::string write_obj(const IndexedMesh& mesh, const WriteOptions& options) {
  detail::check_writable(mesh);
  const bool has_vt = !mesh.texcoord_indices.empty();
  const bool has_vn = !mesh.normal_indices.empty();
  std::string out;
  out.reserve(mesh.positions.size() * 40 + mesh.indices.size() * (has_vt || has_vn ? 20 : 8) + 64);
  out += "# hedge OBJ export\n";
  for (const Vec3& v : mesh.positions) {
    out += "v ";
    detail::append_vec3_line(out, v, options.precision);
  }
  if (has_vt) {
    for (const Vec2& t : mesh.texcoords) {
      out += "vt ";
      detail::append_float(out, t.x, options.precision);
      out += ' ';
      detail::append_float(out, t.y, options.precision);
      out += '\n';
    }
  }
  if (has_vn) {
    for (const Vec3& n : mesh.normals) {
      out += "vn ";
      detail::append_vec3_line(out, n, options.precision);
    }
  }
  // Runs of faces of one submesh under "usemtl submesh_N", in face order.
  const bool submeshes = !mesh.face_submeshes.empty() && mesh.face_submeshes.size() == mesh.face_count();
  std::size_t face = 0;
  detail::for_each_face(mesh, [&](std::size_t first, std::size_t n) {
    if (submeshes && (face == 0 || mesh.face_submeshes[face] != mesh.face_submeshes[face - 1])) {
      out += "usemtl submesh_";
      out += std::to_string(mesh.face_submeshes[face]);
      out += '\n';
    }
    ++face;
    out += 'f';
    for (std::size_t c = first; c < first + n; ++c) {
      out += ' ';
      detail::append_uint(out, std::uint64_t{mesh.indices[c]} + 1);
      if (has_vt || has_vn) {
        out += '/';
        if (has_vt) detail::append_uint(out, std::uint64_t{mesh.texcoord_indices[c]} + 1);
        if (has_vn) {
          out += '/';
          detail::append_uint(out, std::uint64_t{mesh.normal_indices[c]} + 1);
        }
      }
    }
    out += '\n';
  });
  return out;
}

}  // namespace hedge
