// Object File Format (Geomview / Princeton): OFF, COFF, NOFF, CNOFF, STOFF... headers, '#' comments,
// the counts line (possibly on the header line), one vertex per line and one face per line. Vertex
// normals, colours and texture coordinates after x y z, and face colours after the indices, are
// skipped: their number of values is not fixed by the header, which is why vertices and faces are
// read line by line rather than as a token stream.

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "hedge/io/io.h"
#include "parse_util.h"

namespace hedge {

namespace {

using detail::TextCursor;

// Reads the header keyword. Returns false when the file starts with the counts (the keyword is
// optional in the specification).
bool read_keyword(TextCursor& in) {
  in.skip_space('#');
  const char* before = in.p;
  const std::uint64_t line = in.line;
  const std::string_view keyword = in.token();
  if (keyword.empty()) in.fail("expected an OFF header, got end of file");
  if (keyword.size() < 3 || keyword.substr(keyword.size() - 3) != "OFF") {
    std::int64_t count = 0;
    if (detail::parse_int(keyword.data(), keyword.data() + keyword.size(), count) ==
        keyword.data() + keyword.size()) {
      in.p = before;
      in.line = line;
      return false;
    }
    in.fail("expected an OFF header ('OFF', 'COFF', 'NOFF', ...), got " + detail::quote(keyword));
  }
  for (std::string_view prefix = keyword.substr(0, keyword.size() - 3); !prefix.empty();) {
    if (prefix.substr(0, 2) == "ST") {
      prefix.remove_prefix(2);
    } else if (prefix[0] == 'C' || prefix[0] == 'N') {
      prefix.remove_prefix(1);
    } else if (prefix[0] == '4' || prefix[0] == 'n') {
      in.fail("unsupported OFF variant " + detail::quote(keyword) + " (only 3D OFF is supported)");
    } else {
      in.fail("expected an OFF header ('OFF', 'COFF', 'NOFF', ...), got " + detail::quote(keyword));
    }
  }
  if (!in.at_eol() && in.p < in.end && *in.p != '#') {
    const char* save = in.p;
    if (in.token() == "BINARY") in.fail("binary OFF is not supported");
    in.p = save;
  }
  return true;
}

std::uint32_t read_count(TextCursor& in, const char* what) {
  in.skip_space('#');
  std::int64_t n = 0;
  if (!in.integer(n)) in.fail(std::string("expected the number of ") + what + ", got " + in.got());
  if (n < 0) in.fail(std::string("negative number of ") + what + ": " + std::to_string(n));
  if (n >= std::numeric_limits<std::uint32_t>::max())
    in.fail(std::string("the header claims ") + std::to_string(n) + " " + what +
            ", more than this library supports");
  return static_cast<std::uint32_t>(n);
}

// Moves to the next line holding data (skipping blank and comment lines).
void next_record(TextCursor& in, const char* what, std::uint32_t i, std::uint32_t n) {
  in.skip_space('#');
  if (in.p == in.end)
    in.fail(std::string("expected ") + what + " " + std::to_string(i) + " of " + std::to_string(n) +
            ", got end of file");
}

}  // namespace

IndexedMesh read_off(std::string_view data, const std::string& name) {
  TextCursor in(data, name);
  read_keyword(in);
  const std::uint32_t nv = read_count(in, "vertices");
  const std::uint32_t nf = read_count(in, "faces");
  // Every vertex takes at least "0 0 0" and a separator, every face "0" and a separator: a header
  // claiming more than the remaining bytes can hold is rejected before anything is allocated.
  const std::uint64_t needed = 6ull * nv + 2ull * nf;
  if (needed > in.bytes_left() + 1)
    in.fail("the header claims " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
            " faces, but only " + std::to_string(in.bytes_left()) + " bytes follow");
  // The edge count is optional and meaningless for a polygon mesh.
  in.skip_line();

  IndexedMesh mesh;
  mesh.positions.reserve(nv);
  mesh.face_sizes.reserve(nf);
  mesh.indices.reserve(std::min<std::uint64_t>(3ull * nf, in.bytes_left() / 2));
  for (std::uint32_t i = 0; i < nv; ++i) {
    next_record(in, "vertex", i, nv);
    Vec3 v;
    for (int k = 0; k < 3; ++k) {
      if (!in.number(v[static_cast<std::size_t>(k)]))
        in.fail("vertex " + std::to_string(i) + ": expected 3 coordinates, got " + in.got());
    }
    if (!is_finite(v)) in.fail("vertex " + std::to_string(i) + " has a non-finite coordinate");
    mesh.positions.push_back(v);
    in.skip_line();
  }
  for (std::uint32_t f = 0; f < nf; ++f) {
    next_record(in, "face", f, nf);
    std::int64_t n = 0;
    if (!in.integer(n))
      in.fail("face " + std::to_string(f) + ": expected the number of corners, got " + in.got());
    if (n < 1 || n >= std::numeric_limits<std::uint32_t>::max())
      in.fail("face " + std::to_string(f) + ": invalid number of corners " + std::to_string(n));
    for (std::int64_t c = 0; c < n; ++c) {
      std::int64_t index = 0;
      if (!in.integer(index))
        in.fail("face " + std::to_string(f) + ": expected " + std::to_string(n) + " vertex indices, got " +
                in.got());
      if (index < 0 || index >= nv)
        in.fail("face " + std::to_string(f) + ": vertex index " + std::to_string(index) +
                " is out of range (" + std::to_string(nv) + " vertices)");
      mesh.indices.push_back(static_cast<std::uint32_t>(index));
    }
    if (n < 3) mesh.warnings.push_back({in.name, in.line, -1, detail::short_face_message(f, std::size_t(n))});
    mesh.face_sizes.push_back(static_cast<std::uint32_t>(n));
    // Colour values may follow the indices.
    in.skip_line();
  }
  detail::compact_face_sizes(mesh);
  return mesh;
}

std::string write_off(const IndexedMesh& mesh, const WriteOptions& options) {
  detail::check_writable(mesh);
  std::string out;
  out.reserve(mesh.positions.size() * 36 + mesh.indices.size() * 8 + 64);
  out += "OFF\n";
  detail::append_uint(out, mesh.positions.size());
  out += ' ';
  detail::append_uint(out, mesh.face_count());
  out += " 0\n";
  for (const Vec3& v : mesh.positions) detail::append_vec3_line(out, v, options.precision);
  detail::append_counted_faces(out, mesh);
  return out;
}

}  // namespace hedge
