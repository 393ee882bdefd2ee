// Stanford PLY: ascii, binary_little_endian and binary_big_endian. Reads the "vertex" element
// (x y z of any numeric type; nx ny nz as per-vertex normals; u v / s t / texture_u texture_v as
// per-vertex texture coordinates), the "face" element's vertex_indices (or vertex_index) list of any
// count and index type, and the "tristrips" element (-1 restarts a strip). Every other element and
// property, list or scalar, is skipped.
//
// Per-vertex attributes become pools with one entry per vertex, and the per-corner index arrays
// equal the vertex indices, as IndexedMesh specifies for per-vertex data.

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hedge/io/io.h"
#include "parse_util.h"

namespace hedge {

namespace {

using detail::TextCursor;

enum class Type : std::uint8_t { none, i8, u8, i16, u16, i32, u32, f32, f64 };

std::size_t type_size(Type t) {
  switch (t) {
    case Type::i8:
    case Type::u8:
      return 1;
    case Type::i16:
    case Type::u16:
      return 2;
    case Type::i32:
    case Type::u32:
    case Type::f32:
      return 4;
    case Type::f64:
      return 8;
    case Type::none:
      break;
  }
  return 0;
}

bool is_integer(Type t) { return t != Type::f32 && t != Type::f64 && t != Type::none; }
bool is_signed(Type t) { return t == Type::i8 || t == Type::i16 || t == Type::i32; }

Type parse_type(std::string_view s) {
  if (s == "char" || s == "int8") return Type::i8;
  if (s == "uchar" || s == "uint8") return Type::u8;
  if (s == "short" || s == "int16") return Type::i16;
  if (s == "ushort" || s == "uint16") return Type::u16;
  if (s == "int" || s == "int32") return Type::i32;
  if (s == "uint" || s == "uint32") return Type::u32;
  if (s == "float" || s == "float32") return Type::f32;
  if (s == "double" || s == "float64") return Type::f64;
  return Type::none;
}

struct Property {
  std::string name;
  Type type = Type::none;        // the value type (the item type for a list)
  Type count_type = Type::none;  // the list count type; none for a scalar
  bool is_list() const { return count_type != Type::none; }
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

enum class Encoding { ascii, little, big };

struct Header {
  Encoding encoding = Encoding::ascii;
  std::vector<Element> elements;
};

// Reads the header; leaves `in` at the first byte of the body.
Header read_header(TextCursor& in) {
  if (in.token() != "ply" || !in.at_eol()) in.fail("not a PLY file: expected 'ply' on the first line");
  in.skip_line();
  Header h;
  bool have_format = false;
  for (;;) {
    if (in.p == in.end) in.fail("expected 'end_header', got end of file");
    const std::string_view keyword = in.token();
    if (keyword.empty()) {
      in.skip_line();
    } else if (keyword == "comment" || keyword == "obj_info") {
      in.skip_line();
    } else if (keyword == "format") {
      const std::string_view f = in.token();
      if (f == "ascii") {
        h.encoding = Encoding::ascii;
      } else if (f == "binary_little_endian") {
        h.encoding = Encoding::little;
      } else if (f == "binary_big_endian") {
        h.encoding = Encoding::big;
      } else {
        in.fail("expected ascii, binary_little_endian or binary_big_endian after 'format', got " +
                detail::quote(f));
      }
      have_format = true;
      in.skip_line();
    } else if (keyword == "element") {
      Element e;
      e.name = std::string(in.token());
      if (e.name.empty()) in.fail("expected an element name after 'element'");
      std::int64_t count = 0;
      if (!in.integer(count) || count < 0)
        in.fail("expected the number of '" + e.name + "' elements, got " + in.got());
      e.count = static_cast<std::uint64_t>(count);
      h.elements.push_back(std::move(e));
      in.skip_line();
    } else if (keyword == "property") {
      if (h.elements.empty()) in.fail("'property' before any 'element'");
      Property prop;
      std::string_view t = in.token();
      if (t == "list") {
        const std::string_view ct = in.token();
        prop.count_type = parse_type(ct);
        if (!is_integer(prop.count_type))
          in.fail("expected an integer type for the list count, got " + detail::quote(ct));
        t = in.token();
      }
      prop.type = parse_type(t);
      if (prop.type == Type::none) in.fail("expected a property type, got " + detail::quote(t));
      prop.name = std::string(in.token());
      if (prop.name.empty()) in.fail("expected a property name, got end of line");
      h.elements.back().properties.push_back(std::move(prop));
      in.skip_line();
    } else if (keyword == "end_header") {
      if (!in.at_eol()) in.fail("expected a newline after 'end_header', got " + in.got());
      if (!have_format) in.fail("missing 'format' line in the header");
      // Exactly one line terminator follows; the binary body starts right after it.
      if (in.p < in.end) {
        ++in.p;
        ++in.line;
      }
      return h;
    } else {
      in.fail("unknown header keyword " + detail::quote(keyword));
    }
  }
}

// Where a value sits, for error messages: a line (ascii) or a byte offset (binary).
struct Location {
  std::uint64_t line = 0;
  std::int64_t offset = -1;
};

// Reads scalar values from a binary body, checking every access against the end.
class BinarySource {
 public:
  BinarySource(const char* begin, const char* body, const char* end, bool big, const std::string& name)
      : begin_(begin), p_(body), end_(end), big_(big), name_(name) {}

  Location where() const { return {0, p_ - begin_}; }
  [[noreturn]] void fail(const std::string& message, Location at) const {
    throw IoError(name_, 0, at.offset, message);
  }
  ReadWarning warning(const std::string& message, Location at) const {
    return {name_, 0, at.offset, message};
  }
  std::uint64_t bytes_left() const { return static_cast<std::uint64_t>(end_ - p_); }

  double real(Type t) {
    need(type_size(t));
    double v = 0;
    switch (t) {
      case Type::f32:
        v = detail::load<float>(p_, big_);
        break;
      case Type::f64:
        v = detail::load<double>(p_, big_);
        break;
      default:
        v = static_cast<double>(decode_int(t));
        break;
    }
    p_ += type_size(t);
    return v;
  }

  // An integer value (the caller guarantees an integer type).
  std::int64_t integer(Type t) {
    need(type_size(t));
    const std::int64_t v = decode_int(t);
    p_ += type_size(t);
    return v;
  }

  void skip(Type t, std::uint64_t n = 1) {
    const std::uint64_t bytes = n * type_size(t);
    if (n > bytes_left() || bytes > bytes_left()) truncated();
    p_ += bytes;
  }

 private:
  std::int64_t decode_int(Type t) const {
    switch (t) {
      case Type::i8:
        return static_cast<std::int8_t>(*p_);
      case Type::u8:
        return static_cast<std::uint8_t>(*p_);
      case Type::i16:
        return detail::load<std::int16_t>(p_, big_);
      case Type::u16:
        return detail::load<std::uint16_t>(p_, big_);
      case Type::i32:
        return detail::load<std::int32_t>(p_, big_);
      case Type::u32:
        return detail::load<std::uint32_t>(p_, big_);
      default:
        return 0;
    }
  }
  void need(std::size_t n) const {
    if (static_cast<std::size_t>(end_ - p_) < n) truncated();
  }
  [[noreturn]] void truncated() const { fail("unexpected end of file (truncated binary data)", where()); }

  const char* begin_;
  const char* p_;
  const char* end_;
  bool big_;
  const std::string& name_;
};

// Reads whitespace-separated values from an ascii body.
class AsciiSource {
 public:
  explicit AsciiSource(TextCursor& in) : in_(in) {}

  Location where() const { return {in_.line, -1}; }
  [[noreturn]] void fail(const std::string& message, Location at) const {
    throw IoError(in_.name, at.line, -1, message);
  }
  ReadWarning warning(const std::string& message, Location at) const {
    return {in_.name, at.line, -1, message};
  }
  std::uint64_t bytes_left() const { return in_.bytes_left(); }

  double real(Type t) {
    in_.skip_space(0);
    if (is_integer(t)) return static_cast<double>(integer(t));
    float v = 0;
    if (!in_.number(v)) fail("expected a number, got " + in_.got(), where());
    return v;
  }

  std::int64_t integer(Type) {
    in_.skip_space(0);
    std::int64_t v = 0;
    if (!in_.integer(v)) fail("expected an integer, got " + in_.got(), where());
    return v;
  }

  void skip(Type, std::uint64_t n = 1) {
    for (std::uint64_t i = 0; i < n; ++i) {
      in_.skip_space(0);
      if (in_.token().empty()) fail("expected a value, got end of file", where());
    }
  }

 private:
  TextCursor& in_;
};

// Slots of the vertex properties the reader keeps.
enum Slot : int { kX, kY, kZ, kNx, kNy, kNz, kU, kV, kSlots };

std::optional<int> vertex_slot(std::string_view n) {
  if (n == "x") return kX;
  if (n == "y") return kY;
  if (n == "z") return kZ;
  if (n == "nx") return kNx;
  if (n == "ny") return kNy;
  if (n == "nz") return kNz;
  if (n == "u" || n == "s" || n == "texture_u" || n == "texture_s") return kU;
  if (n == "v" || n == "t" || n == "texture_v" || n == "texture_t") return kV;
  return std::nullopt;
}

template <typename Source>
class BodyReader {
 public:
  // vertex_count: the header's count of the 'vertex' element (0 without one). Faces are checked
  // against it as they are read, so the first index out of range is the one reported, even in a
  // file that puts its faces before its vertices (PLY allows any element order).
  BodyReader(Source& src, IndexedMesh& mesh, std::uint64_t vertex_count)
      : src_(src), mesh_(mesh), vertex_count_(vertex_count) {}

  void read(const Element& e) {
    std::uint64_t min_record = 0;
    std::size_t values = 0;
    for (const Property& p : e.properties) {
      min_record += type_size(p.is_list() ? p.count_type : p.type);
      ++values;
    }
    if (e.count == 0) return;
    if (values == 0) {  // records of no bytes: nothing to read, but vertices must have positions
      if (e.name == "vertex") src_.fail("the vertex element lacks a scalar x, y or z property", src_.where());
      return;
    }
    // A binary record takes at least min_record bytes, an ascii value at least one character and
    // a separator: reject a count the rest of the file cannot hold before looping or allocating.
    constexpr bool binary = std::is_same_v<Source, BinarySource>;
    const std::uint64_t per_record = binary ? min_record : 2 * values;
    // The last ascii value needs no separator.
    if (e.count > (src_.bytes_left() + (binary ? 0 : 1)) / per_record)
      src_.fail("the header claims " + std::to_string(e.count) + " '" + e.name + "' elements, but only " +
                    std::to_string(src_.bytes_left()) + " bytes remain",
                src_.where());
    if (e.name == "vertex") {
      read_vertices(e);
    } else if (e.name == "face" || e.name == "tristrips") {
      read_faces(e, e.name == "tristrips");
    } else {
      skip_element(e);
    }
  }

  void finish() {
    const bool corners = !mesh_.indices.empty();
    if (has_normals_ && corners) {
      mesh_.normal_indices = mesh_.indices;
    } else {
      mesh_.normals.clear();
    }
    if (has_texcoords_ && corners) {
      mesh_.texcoord_indices = mesh_.indices;
    } else {
      mesh_.texcoords.clear();
    }
    detail::compact_face_sizes(mesh_);
  }

 private:
  void skip_element(const Element& e) {
    for (std::uint64_t i = 0; i < e.count; ++i) {
      for (const Property& p : e.properties) {
        if (p.is_list()) {
          const std::int64_t n = list_count(p);
          src_.skip(p.type, static_cast<std::uint64_t>(n));
        } else {
          src_.skip(p.type);
        }
      }
    }
  }

  std::int64_t list_count(const Property& p) {
    const Location at = src_.where();
    const std::int64_t n = src_.integer(p.count_type);
    if (n < 0) src_.fail("negative list length " + std::to_string(n) + " for '" + p.name + "'", at);
    return n;
  }

  void read_vertices(const Element& e) {
    if (vertices_read_) src_.fail("more than one 'vertex' element", src_.where());
    vertices_read_ = true;
    if (e.count >= std::numeric_limits<std::uint32_t>::max())
      src_.fail("too many vertices: " + std::to_string(e.count), src_.where());
    std::vector<int> slot(e.properties.size(), -1);
    bool have[kSlots] = {};
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
      const Property& p = e.properties[i];
      const auto s = vertex_slot(p.name);
      if (s && !p.is_list() && !have[*s]) {
        slot[i] = *s;
        have[*s] = true;
      }
    }
    if (!have[kX] || !have[kY] || !have[kZ])
      src_.fail("the vertex element lacks a scalar x, y or z property", src_.where());
    has_normals_ = have[kNx] && have[kNy] && have[kNz];
    has_texcoords_ = have[kU] && have[kV];
    mesh_.positions.reserve(e.count);
    if (has_normals_) mesh_.normals.reserve(e.count);
    if (has_texcoords_) mesh_.texcoords.reserve(e.count);
    double v[kSlots] = {};
    for (std::uint64_t i = 0; i < e.count; ++i) {
      const Location at = src_.where();
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        if (p.is_list()) {
          src_.skip(p.type, static_cast<std::uint64_t>(list_count(p)));
        } else if (slot[k] >= 0) {
          v[slot[k]] = src_.real(p.type);
        } else {
          src_.skip(p.type);
        }
      }
      const Vec3 pos{detail::narrow(v[kX]), detail::narrow(v[kY]), detail::narrow(v[kZ])};
      if (!is_finite(pos)) src_.fail("vertex " + std::to_string(i) + " has a non-finite coordinate", at);
      mesh_.positions.push_back(pos);
      if (has_normals_) {
        const Vec3 n{detail::narrow(v[kNx]), detail::narrow(v[kNy]), detail::narrow(v[kNz])};
        if (!is_finite(n)) src_.fail("vertex " + std::to_string(i) + " has a non-finite normal", at);
        mesh_.normals.push_back(n);
      }
      if (has_texcoords_) {
        const Vec2 t{detail::narrow(v[kU]), detail::narrow(v[kV])};
        if (!is_finite(t))
          src_.fail("vertex " + std::to_string(i) + " has a non-finite texture coordinate", at);
        mesh_.texcoords.push_back(t);
      }
    }
  }

  // Checks one vertex index of face `face` read at `at`; returns it as a 32-bit index.
  std::uint32_t check_index(std::int64_t index, std::uint64_t face, Location at) {
    if (index < 0 || index >= std::numeric_limits<std::uint32_t>::max() ||
        static_cast<std::uint64_t>(index) >= vertex_count_)
      src_.fail("face " + std::to_string(face) + ": vertex index " + std::to_string(index) +
                    " is out of range (" + std::to_string(vertex_count_) + " vertices)",
                at);
    return static_cast<std::uint32_t>(index);
  }

  void read_faces(const Element& e, bool strips) {
    std::size_t list = e.properties.size();
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
      const Property& p = e.properties[i];
      if (p.is_list() && (p.name == "vertex_indices" || p.name == "vertex_index")) {
        list = i;
        break;
      }
    }
    if (list == e.properties.size())
      src_.fail("the '" + e.name + "' element has no vertex_indices list", src_.where());
    const Property& lp = e.properties[list];
    if (!is_integer(lp.type))
      src_.fail("the '" + e.name + "' element's " + lp.name + " list must have an integer type",
                src_.where());
    if (!strips) {
      mesh_.face_sizes.reserve(mesh_.face_sizes.size() + e.count);
      mesh_.indices.reserve(mesh_.indices.size() + 3 * e.count);
    }
    // An unsigned index type stores the strip restart -1 as its largest value.
    const std::int64_t restart =
        is_signed(lp.type) ? -1 : static_cast<std::int64_t>((1ull << (8 * type_size(lp.type))) - 1);
    for (std::uint64_t i = 0; i < e.count; ++i) {
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        if (!p.is_list()) {
          src_.skip(p.type);
          continue;
        }
        // Where a face record starts: its count's byte (binary), its line (text, known once the
        // count is read, past any line break before it).
        Location record_at = src_.where();
        const std::uint64_t n = static_cast<std::uint64_t>(list_count(p));
        record_at.line = src_.where().line;
        if (k != list) {
          src_.skip(p.type, n);
        } else if (strips) {
          read_strip(n, lp.type, restart);
        } else {
          // A face without corners has no meaning in any format; rejecting it keeps every reader's
          // output writable.
          if (n == 0) src_.fail("face " + std::to_string(face_number_) + " has no corners", src_.where());
          if (n > std::numeric_limits<std::uint32_t>::max())
            src_.fail("face " + std::to_string(face_number_) + " has too many corners", src_.where());
          for (std::uint64_t c = 0; c < n; ++c) {
            const Location at = src_.where();
            mesh_.indices.push_back(check_index(src_.integer(lp.type), face_number_, at));
          }
          if (n < 3)
            mesh_.warnings.push_back(src_.warning(detail::short_face_message(face_number_, n), record_at));
          mesh_.face_sizes.push_back(static_cast<std::uint32_t>(n));
          ++face_number_;
        }
      }
    }
  }

  // Decodes one triangle strip: triangle k of the strip is (s[k], s[k+1], s[k+2]) for even k and
  // (s[k+1], s[k], s[k+2]) for odd k, so that all share one orientation. Triangles with a repeated
  // index join strips together and carry no area: they are dropped.
  void read_strip(std::uint64_t n, Type t, std::int64_t restart) {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    std::uint64_t k = 0;  // position within the current strip
    for (std::uint64_t i = 0; i < n; ++i) {
      const Location at = src_.where();
      const std::int64_t raw = src_.integer(t);
      if (raw == restart) {
        k = 0;
        continue;
      }
      const std::uint32_t c = check_index(raw, face_number_, at);
      if (k >= 2 && a != b && b != c && a != c) {
        const bool odd = (k & 1) != 0;
        mesh_.indices.push_back(odd ? b : a);
        mesh_.indices.push_back(odd ? a : b);
        mesh_.indices.push_back(c);
        mesh_.face_sizes.push_back(3);
        ++face_number_;
      }
      a = b;
      b = c;
      ++k;
    }
  }

  Source& src_;
  IndexedMesh& mesh_;
  bool vertices_read_ = false;
  bool has_normals_ = false;
  bool has_texcoords_ = false;
  std::uint64_t face_number_ = 0;
  std::uint64_t vertex_count_;
};

template <typename Source>
IndexedMesh read_body(Source& src, const Header& h) {
  IndexedMesh mesh;
  std::uint64_t vertex_count = 0;
  for (const Element& e : h.elements)
    if (e.name == "vertex") {
      vertex_count = e.count;
      break;
    }
  BodyReader<Source> reader(src, mesh, vertex_count);
  for (const Element& e : h.elements) reader.read(e);
  reader.finish();
  return mesh;
}

}  // namespace

IndexedMesh read_ply(std::string_view data, const std::string& name) {
  TextCursor in(data, name);
  const Header h = read_header(in);
  if (h.encoding == Encoding::ascii) {
    AsciiSource src(in);
    return read_body(src, h);
  }
  BinarySource src(data.data(), in.p, in.end, h.encoding == Encoding::big, name);
  return read_body(src, h);
}

namespace {

// Per-vertex values of a per-corner attribute, when every corner of a vertex carries the same value
// (PLY can only store per-vertex attributes). Vertices no face uses get a zero value.
template <typename T>
std::optional<std::vector<T>> per_vertex(const IndexedMesh& mesh, const std::vector<T>& pool,
                                         const std::vector<std::uint32_t>& corner_index) {
  if (corner_index.empty()) return std::nullopt;
  std::vector<T> out(mesh.positions.size());
  std::vector<bool> set(mesh.positions.size(), false);
  for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
    const std::uint32_t v = mesh.indices[c];
    const T& value = pool[corner_index[c]];
    if (!set[v]) {
      out[v] = value;
      set[v] = true;
    } else if (!(out[v] == value)) {
      return std::nullopt;
    }
  }
  return out;
}

}  // namespace

std::string write_ply(const IndexedMesh& mesh, const WriteOptions& options) {
  detail::check_writable(mesh);
  const auto normals = per_vertex(mesh, mesh.normals, mesh.normal_indices);
  const auto texcoords = per_vertex(mesh, mesh.texcoords, mesh.texcoord_indices);
  std::uint32_t max_face = 0;
  detail::for_each_face(mesh, [&](std::size_t, std::size_t n) {
    max_face = std::max(max_face, static_cast<std::uint32_t>(n));
  });
  const bool wide_count = max_face > 255;

  std::string out;
  out += "ply\nformat ";
  out += options.binary ? "binary_little_endian" : "ascii";
  out += " 1.0\ncomment hedge PLY export\nelement vertex ";
  detail::append_uint(out, mesh.positions.size());
  out += "\nproperty float x\nproperty float y\nproperty float z\n";
  if (normals) out += "property float nx\nproperty float ny\nproperty float nz\n";
  if (texcoords) out += "property float u\nproperty float v\n";
  out += "element face ";
  detail::append_uint(out, mesh.face_count());
  out += wide_count ? "\nproperty list uint uint vertex_indices\n"
                    : "\nproperty list uchar uint vertex_indices\n";
  out += "end_header\n";

  const std::size_t per_vertex_values = 3 + (normals ? 3 : 0) + (texcoords ? 2 : 0);
  if (options.binary) {
    out.reserve(out.size() + mesh.positions.size() * per_vertex_values * 4 + mesh.face_count() * 4 +
                mesh.indices.size() * 4);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      const Vec3& p = mesh.positions[i];
      detail::store_le(out, p.x);
      detail::store_le(out, p.y);
      detail::store_le(out, p.z);
      if (normals) {
        const Vec3& n = (*normals)[i];
        detail::store_le(out, n.x);
        detail::store_le(out, n.y);
        detail::store_le(out, n.z);
      }
      if (texcoords) {
        const Vec2& t = (*texcoords)[i];
        detail::store_le(out, t.x);
        detail::store_le(out, t.y);
      }
    }
    detail::for_each_face(mesh, [&](std::size_t first, std::size_t n) {
      if (wide_count) {
        detail::store_le(out, static_cast<std::uint32_t>(n));
      } else {
        out += static_cast<char>(static_cast<unsigned char>(n));
      }
      for (std::size_t c = first; c < first + n; ++c) detail::store_le(out, mesh.indices[c]);
    });
    return out;
  }

  out.reserve(out.size() + mesh.positions.size() * per_vertex_values * 12 + mesh.indices.size() * 8);
  auto put = [&](float f, bool last) {
    detail::append_float(out, f, options.precision);
    out += last ? '\n' : ' ';
  };
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3& p = mesh.positions[i];
    put(p.x, false);
    put(p.y, false);
    put(p.z, !normals && !texcoords);
    if (normals) {
      const Vec3& n = (*normals)[i];
      put(n.x, false);
      put(n.y, false);
      put(n.z, !texcoords);
    }
    if (texcoords) {
      const Vec2& t = (*texcoords)[i];
      put(t.x, false);
      put(t.y, true);
    }
  }
  detail::append_counted_faces(out, mesh);
  return out;
}

}  // namespace hedge
