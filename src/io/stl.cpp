// STL, ASCII and binary. The reader returns the triangle soup as stored: three new vertices per
// triangle, no welding (read_mesh welds by exact position through default_build_options). Facet
// normals in the file are ignored: they are often missing, stale or NaN, and the geometry defines
// them anyway.
//
// Binary detection: many binary files start their 80-byte header with "solid", like ASCII ones.
// A file whose size is exactly 84 + 50 x (the triangle count at byte 80) is binary whatever its
// header says; otherwise a leading "solid" with no NUL byte nearby means ASCII.

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "hedge/io/io.h"
#include "parse_util.h"

namespace hedge {

namespace {

using detail::TextCursor;

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kTriangleBytes = 50;

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const char x = (a[i] >= 'A' && a[i] <= 'Z') ? static_cast<char>(a[i] - 'A' + 'a') : a[i];
    if (x != b[i]) return false;
  }
  return true;
}

bool starts_with_solid(std::string_view data) {
  std::size_t i = 0;
  while (i < data.size() && detail::is_space(data[i])) ++i;
  return data.size() - i >= 5 && iequals(data.substr(i, 5), "solid");
}

IndexedMesh read_binary(std::string_view data, const std::string& name) {
  if (data.size() < kHeaderBytes + 4)
    throw IoError(
        name, 0, static_cast<std::int64_t>(data.size()),
        "not an STL file: too short for a binary STL (84 bytes at least) and no ASCII 'solid' header");
  const auto n = detail::load<std::uint32_t>(data.data() + kHeaderBytes, false);
  const std::uint64_t needed = kHeaderBytes + 4 + kTriangleBytes * std::uint64_t{n};
  if (needed > data.size())
    throw IoError(name, 0, kHeaderBytes,
                  "binary STL header claims " + std::to_string(n) + " triangles (" + std::to_string(needed) +
                      " bytes), but the file has " + std::to_string(data.size()) + " bytes");
  IndexedMesh mesh;
  mesh.positions.resize(3 * std::size_t{n});
  mesh.indices.resize(3 * std::size_t{n});
  const char* p = data.data() + kHeaderBytes + 4;
  for (std::uint32_t t = 0; t < n; ++t, p += kTriangleBytes) {
    for (std::uint32_t k = 0; k < 3; ++k) {
      const char* q = p + 12 + 12 * k;
      const Vec3 v{detail::load<float>(q, false), detail::load<float>(q + 4, false),
                   detail::load<float>(q + 8, false)};
      const std::size_t i = 3 * std::size_t{t} + k;
      if (!is_finite(v))
        throw IoError(name, 0, q - data.data(),
                      "triangle " + std::to_string(t) + ", vertex " + std::to_string(k) +
                          " has a non-finite coordinate");
      mesh.positions[i] = v;
      mesh.indices[i] = static_cast<std::uint32_t>(i);
    }
  }
  return mesh;
}

void expect(TextCursor& in, std::string_view keyword) {
  in.skip_space(0);
  const std::string_view t = in.token();
  if (!iequals(t, keyword)) {
    in.p = t.data();
    in.fail("expected '" + std::string(keyword) + "', got " +
            (t.empty() ? std::string("end of file") : in.got()));
  }
}

float ascii_number(TextCursor& in, const char* what) {
  in.skip_space(0);
  float v = 0;
  if (!in.number(v)) in.fail(std::string("expected ") + what + ", got " + in.got());
  return v;
}

IndexedMesh read_ascii(std::string_view data, const std::string& name) {
  TextCursor in(data, name);
  IndexedMesh mesh;
  // An ASCII facet takes well over 100 bytes; this bounds the reservation by the input size.
  mesh.positions.reserve(data.size() / 40);
  mesh.indices.reserve(data.size() / 40);
  for (;;) {
    expect(in, "solid");
    in.skip_line();  // the solid's name
    for (;;) {
      in.skip_space(0);
      const char* at = in.p;
      const std::string_view t = in.token();
      if (iequals(t, "endsolid")) {
        in.skip_line();
        break;
      }
      if (!iequals(t, "facet")) {
        in.p = at;
        in.fail("expected 'facet' or 'endsolid', got " + (t.empty() ? std::string("end of file") : in.got()));
      }
      expect(in, "normal");
      // The normal is not kept, and old exporters write NaNs as "-1.#IND": take any three tokens.
      for (int k = 0; k < 3; ++k) {
        in.skip_space(0);
        if (in.token().empty()) in.fail("expected a facet normal component, got end of file");
      }
      expect(in, "outer");
      expect(in, "loop");
      for (int k = 0; k < 3; ++k) {
        expect(in, "vertex");
        Vec3 v;
        v.x = ascii_number(in, "a vertex coordinate");
        v.y = ascii_number(in, "a vertex coordinate");
        v.z = ascii_number(in, "a vertex coordinate");
        if (!is_finite(v))
          in.fail("vertex " + std::to_string(mesh.positions.size()) + " has a non-finite coordinate");
        if (mesh.positions.size() >= std::numeric_limits<std::uint32_t>::max()) in.fail("too many vertices");
        mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
        mesh.positions.push_back(v);
      }
      expect(in, "endloop");
      expect(in, "endfacet");
    }
    // Several solids may follow one another.
    in.skip_space(0);
    if (in.p == in.end) break;
  }
  return mesh;
}

}  // namespace

IndexedMesh read_stl(std::string_view data, const std::string& name) {
  if (data.size() >= kHeaderBytes + 4) {
    const auto n = detail::load<std::uint32_t>(data.data() + kHeaderBytes, false);
    if (kHeaderBytes + 4 + kTriangleBytes * std::uint64_t{n} == data.size()) return read_binary(data, name);
  }
  const bool text = starts_with_solid(data) &&
                    std::memchr(data.data(), '\0', std::min<std::size_t>(data.size(), 1024)) == nullptr;
  return text ? read_ascii(data, name) : read_binary(data, name);
}

namespace {

Vec3 facet_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
  // Double precision: thin triangles lose their normal direction in float.
  const Vec3d n = cross(to_double(b) - to_double(a), to_double(c) - to_double(a));
  const double len = norm(n);
  return len > 0 ? to_float(n * (1.0 / len)) : Vec3{};
}

template <typename F>
void for_each_triangle(const IndexedMesh& mesh, F&& f) {
  detail::for_each_face(mesh, [&](std::size_t first, std::size_t n) {
    for (std::size_t k = 1; k + 1 < n; ++k)
      f(mesh.positions[mesh.indices[first]], mesh.positions[mesh.indices[first + k]],
        mesh.positions[mesh.indices[first + k + 1]]);
  });
}

}  // namespace

std::string write_stl(const IndexedMesh& mesh, const WriteOptions& options) {
  detail::check_writable(mesh);
  std::uint64_t triangles = 0;
  detail::for_each_face(mesh, [&](std::size_t, std::size_t n) { triangles += n >= 3 ? n - 2 : 0; });
  std::string out;
  if (options.binary) {
    if (triangles > std::numeric_limits<std::uint32_t>::max())
      throw InvalidInputError("too many triangles for a binary STL file");
    out.reserve(kHeaderBytes + 4 + kTriangleBytes * triangles);
    // The header must not start with "solid", or readers that trust it would take the file for ASCII.
    std::string header = "hedge binary STL";
    header.resize(kHeaderBytes, ' ');
    out += header;
    detail::store_le(out, static_cast<std::uint32_t>(triangles));
    for_each_triangle(mesh, [&](const Vec3& a, const Vec3& b, const Vec3& c) {
      const Vec3 n = facet_normal(a, b, c);
      for (const Vec3* v : {&n, &a, &b, &c}) {
        detail::store_le(out, v->x);
        detail::store_le(out, v->y);
        detail::store_le(out, v->z);
      }
      out += '\0';
      out += '\0';
    });
    return out;
  }
  out.reserve(triangles * 200 + 32);
  out += "solid hedge\n";
  auto put = [&](const Vec3& v) { detail::append_vec3_line(out, v, options.precision); };
  for_each_triangle(mesh, [&](const Vec3& a, const Vec3& b, const Vec3& c) {
    out += "facet normal ";
    put(facet_normal(a, b, c));
    out += " outer loop\n";
    for (const Vec3* v : {&a, &b, &c}) {
      out += "  vertex ";
      put(*v);
    }
    out += " endloop\nendfacet\n";
  });
  out += "endsolid hedge\n";
  return out;
}

}  // namespace hedge
