// Private helpers shared by the format readers and writers: number parsing with std::from_chars
// (or a fallback with the same contract),
// text scanning with line tracking, bounds-checked binary access and error reporting.
#pragma once

#include <algorithm>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <vector>

#include "hedge/core/indexed_mesh.h"
#include "hedge/error.h"

namespace hedge::detail {

//! Blank characters inside a line. '\r' counts as blank so that CRLF files parse like LF files.
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

inline bool is_space(char c) { return is_blank(c) || c == '\n'; }

//! Quotes a piece of input for an error message: at most 24 characters, non-printable bytes as \xNN.
inline std::string quote(std::string_view s) {
  std::string out = "'";
  const std::size_t n = std::min<std::size_t>(s.size(), 24);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (s.size() > n) out += "...";
  return out + "'";
}

//! Describes what stands at `p` in a text: the token there, "end of line" or "end of file".
inline std::string describe_token(const char* p, const char* end) {
  while (p < end && is_blank(*p)) ++p;
  if (p == end) return "end of file";
  if (*p == '\n') return "end of line";
  const char* q = p;
  while (q < end && !is_space(*q)) ++q;
  return quote(std::string_view(p, static_cast<std::size_t>(q - p)));
}

//! Rounds a double to float; out-of-range values become infinities (what IEEE 754 does, spelled out
//! because C++ leaves the conversion of a value beyond float's range undefined).
inline float narrow(double d) {
  constexpr double kOverflow = 0x1.ffffffp127;  // FLT_MAX + half an ulp: rounds to infinity
  if (d >= kOverflow) return std::numeric_limits<float>::infinity();
  if (d <= -kOverflow) return -std::numeric_limits<float>::infinity();
  if (d > std::numeric_limits<float>::max()) return std::numeric_limits<float>::max();
  if (d < -std::numeric_limits<float>::max()) return -std::numeric_limits<float>::max();
  return static_cast<float>(d);
}

//! std::from_chars for float and double. Where the standard library lacks those overloads (it has
//! only the integer ones before libstdc++ 11 and in emscripten's libc++; __cpp_lib_to_chars tells),
//! the same contract is kept through strtof / strtod on a copy of the number's text: the grammar of
//! from_chars's general format (an optional '-', digits with an optional point and exponent, or
//! "inf", "infinity", "nan"; no blanks, no '+', no hexadecimal), correct rounding by the C library,
//! and result_out_of_range, with `out` unchanged, when the value overflows or underflows.
template <typename T>
std::from_chars_result chars_to_floating(const char* first, const char* last, T& out) {
#if defined(__cpp_lib_to_chars)
  return std::from_chars(first, last, out);
#else
  static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>);
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  const auto lower = [](char c) { return static_cast<char>(c | 0x20); };
  const char* p = first;
  if (p != last && *p == '-') ++p;
  const auto word = [&](const char* w) -> const char* {
    const char* q = p;
    for (; *w; ++w, ++q)
      if (q == last || lower(*q) != *w) return nullptr;
    return q;
  };
  if (const char* q = word("infinity")) {
    p = q;
  } else if (const char* r = word("inf")) {
    p = r;
  } else if (const char* n = word("nan")) {
    p = n;
    if (p != last && *p == '(') {
      const char* c = p + 1;
      while (c != last && (digit(*c) || (lower(*c) >= 'a' && lower(*c) <= 'z') || *c == '_')) ++c;
      if (c != last && *c == ')') p = c + 1;
    }
  } else {
    bool any = false;
    while (p != last && digit(*p)) ++p, any = true;
    if (p != last && *p == '.') {
      ++p;
      while (p != last && digit(*p)) ++p, any = true;
    }
    if (!any) return {first, std::errc::invalid_argument};
    if (p != last && (*p == 'e' || *p == 'E')) {
      const char* e = p + 1;
      if (e != last && (*e == '+' || *e == '-')) ++e;
      const char* d = e;
      while (e != last && digit(*e)) ++e;
      if (e != d) p = e;
    }
  }
  const std::string text(first, p);
  char* end = nullptr;
  errno = 0;
  T value;
  if constexpr (std::is_same_v<T, float>)
    value = std::strtof(text.c_str(), &end);
  else
    value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return {first, std::errc::invalid_argument};
  if (errno == ERANGE) return {p, std::errc::result_out_of_range};
  out = value;
  return {p, std::errc()};
#endif
}

//! Parses a float at `p` (no leading blanks); returns the end of the number, or nullptr when there
//! is none. std::from_chars does the work: in libstdc++ 12 it is as fast as a hand-written parser
//! (measured: 15-30 ns per coordinate either way) and exact. A leading '+', which from_chars
//! rejects but some exporters write, is accepted. A value that underflows float becomes 0 (or a
//! subnormal); one that overflows becomes an infinity, which the callers' finiteness checks report.
inline const char* parse_float(const char* p, const char* end, float& out) {
  const char* s = p;
  if (s != end && *s == '+') {
    ++s;
    if (s == end || *s == '-' || *s == '+') return nullptr;
  }
  auto [ptr, ec] = chars_to_floating(s, end, out);
  if (ec == std::errc()) return ptr;
  if (ec != std::errc::result_out_of_range) return nullptr;
  double d = 0;
  auto [ptr2, ec2] = chars_to_floating(s, end, d);
  if (ec2 == std::errc()) {
    out = narrow(d);
    return ptr2;
  }
  // Out of range even for double: the sign of the exponent tells underflow from overflow.
  const bool negative = *s == '-';
  const std::string_view text(s, static_cast<std::size_t>(ptr - s));
  const bool tiny = text.find("e-") != std::string_view::npos || text.find("E-") != std::string_view::npos;
  out = tiny ? 0.0f : std::numeric_limits<float>::infinity();
  if (negative) out = -out;
  return ptr;
}

//! Parses a signed decimal integer at `p` (no leading blanks; a leading '+' is accepted). Returns
//! its end, or nullptr when there is none or it does not fit in 64 bits.
inline const char* parse_int(const char* p, const char* end, std::int64_t& out) {
  const char* s = p;
  if (s != end && *s == '+') {
    ++s;
    if (s == end || *s == '-' || *s == '+') return nullptr;
  }
  auto [ptr, ec] = std::from_chars(s, end, out);
  return ec == std::errc() ? ptr : nullptr;
}

//! True when `p` ends a token: end of input, a blank or a newline.
inline bool at_token_end(const char* p, const char* end) { return p == end || is_space(*p); }

//! A position in a text file with its 1-based line, for the line-oriented readers (OFF, ASCII PLY
//! and STL). Errors name the file and the current line.
struct TextCursor {
  const char* p;
  const char* end;
  const std::string& name;
  std::uint64_t line = 1;

  TextCursor(std::string_view data, const std::string& file_name)
      : p(data.data()), end(data.data() + data.size()), name(file_name) {}

  [[noreturn]] void fail(const std::string& message) const { throw IoError(name, line, -1, message); }

  //! What stands at the cursor, for "expected X, got Y" messages.
  std::string got() const { return describe_token(p, end); }

  std::uint64_t bytes_left() const { return static_cast<std::uint64_t>(end - p); }

  void skip_blanks() {
    while (p < end && is_blank(*p)) ++p;
  }

  //! True at the end of the line or of the input (after blanks).
  bool at_eol() {
    skip_blanks();
    return p == end || *p == '\n';
  }

  //! Moves past the next newline (or to the end).
  void skip_line() {
    // Usually only the newline is left: avoid a memchr call per record.
    skip_blanks();
    if (p < end && *p == '\n') {
      ++p;
      ++line;
      return;
    }
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
    if (nl == nullptr) {
      p = end;
    } else {
      p = static_cast<const char*>(nl) + 1;
      ++line;
    }
  }

  //! Skips blanks, newlines and, when `comment` is not 0, comments from `comment` to the line end.
  void skip_space(char comment) {
    for (;;) {
      skip_blanks();
      if (p == end) return;
      if (*p == '\n') {
        ++p;
        ++line;
      } else if (comment != 0 && *p == comment) {
        skip_line();
      } else {
        return;
      }
    }
  }

  //! The next run of non-space characters on this line (empty at the end of the line).
  std::string_view token() {
    skip_blanks();
    const char* s = p;
    while (p < end && !is_space(*p)) ++p;
    return {s, static_cast<std::size_t>(p - s)};
  }

  //! Parses a float token on the current line; nullopt-like false when there is none.
  bool number(float& out) {
    skip_blanks();
    const char* q = parse_float(p, end, out);
    if (q == nullptr || !at_token_end(q, end)) return false;
    p = q;
    return true;
  }

  bool integer(std::int64_t& out) {
    skip_blanks();
    const char* q = parse_int(p, end, out);
    if (q == nullptr || !at_token_end(q, end)) return false;
    p = q;
    return true;
  }
};

//! The warning for a face of fewer than 3 corners: a file cut in the middle of a face line leaves one.
inline std::string short_face_message(std::uint64_t face, std::uint64_t corners) {
  return "face " + std::to_string(face) + " has " + std::to_string(corners) +
         (corners == 1 ? " corner" : " corners") + "; a face needs at least 3 (the file may be truncated)";
}

//! Replaces face_sizes by the empty "all triangles" form when every face is a triangle.
inline void compact_face_sizes(IndexedMesh& mesh) {
  if (std::all_of(mesh.face_sizes.begin(), mesh.face_sizes.end(), [](std::uint32_t n) { return n == 3; }))
    mesh.face_sizes.clear();
}

// ---------------------------------------------------------------------------------------------------
// Binary access.

template <typename T>
T byte_swap(T v) {
  static_assert(std::is_trivially_copyable_v<T>);
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  std::reverse(b, b + sizeof(T));
  std::memcpy(&v, b, sizeof(T));
  return v;
}

//! Loads a T stored at `p` in little (or big) endian order. The caller has checked the bounds.
template <typename T>
T load(const char* p, bool big_endian) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big)) v = byte_swap(v);
  return v;
}

//! Appends T to `out` in little endian order.
template <typename T>
void store_le(std::string& out, T v) {
  if constexpr (std::endian::native == std::endian::big) v = byte_swap(v);
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.append(b, sizeof(T));
}

// ---------------------------------------------------------------------------------------------------
// Writing numbers.

//! Appends a float: the shortest text that reads back to the same float when precision >= 9 (every
//! float then survives a round trip exactly), else `precision` significant digits.
//! Without the floating-point std::to_chars (see chars_to_floating) the shortest text is found by
//! printing 1 to 9 significant digits until the text reads back to the same float.
inline void append_float(std::string& out, float v, int precision) {
  char buf[64];
#if defined(__cpp_lib_to_chars)
  std::to_chars_result r;
  if (precision >= 9) {
    r = std::to_chars(buf, buf + sizeof(buf), v);
  } else {
    r = std::to_chars(buf, buf + sizeof(buf), v, std::chars_format::general, std::max(precision, 1));
  }
  out.append(buf, static_cast<std::size_t>(r.ptr - buf));
#else
  int n = 0;
  if (precision >= 9) {
    for (int digits = 1; digits <= 9; ++digits) {
      n = std::snprintf(buf, sizeof(buf), "%.*g", digits, static_cast<double>(v));
      if (std::strtof(buf, nullptr) == v) break;
    }
  } else {
    n = std::snprintf(buf, sizeof(buf), "%.*g", std::max(precision, 1), static_cast<double>(v));
  }
  out.append(buf, static_cast<std::size_t>(std::max(n, 0)));
#endif
}

inline void append_uint(std::string& out, std::uint64_t v) {
  char buf[24];
  auto r = std::to_chars(buf, buf + sizeof(buf), v);
  out.append(buf, static_cast<std::size_t>(r.ptr - buf));
}

//! Appends "x y z" and a newline.
inline void append_vec3_line(std::string& out, const Vec3& v, int precision) {
  append_float(out, v.x, precision);
  out += ' ';
  append_float(out, v.y, precision);
  out += ' ';
  append_float(out, v.z, precision);
  out += '\n';
}

}  // namespace hedge::detail

namespace hedge::detail {

//! Checks what the writers rely on: face sizes adding up to the index count, indices within the
//! pools, attribute index arrays of the right length, and finite positions, texture coordinates,
//! normals and colours (the readers refuse a NaN or an infinity, so a file holding one could not be
//! read back). \throw InvalidInputError naming the problem, before anything is written.
void check_writable(const IndexedMesh& mesh);

//! Calls f(first_corner, corner_count) for each face of `mesh` in order.
template <typename F>
void for_each_face(const IndexedMesh& mesh, F&& f) {
  if (mesh.face_sizes.empty()) {
    for (std::size_t c = 0; c + 3 <= mesh.indices.size(); c += 3) f(c, std::size_t{3});
  } else {
    std::size_t c = 0;
    for (std::uint32_t n : mesh.face_sizes) {
      f(c, std::size_t{n});
      c += n;
    }
  }
}

//! Appends one "n i j k ..." line per face: the face list of OFF and of ASCII PLY.
inline void append_counted_faces(std::string& out, const IndexedMesh& mesh) {
  for_each_face(mesh, [&](std::size_t first, std::size_t n) {
    append_uint(out, n);
    for (std::size_t c = first; c < first + n; ++c) {
      out += ' ';
      append_uint(out, mesh.indices[c]);
    }
    out += '\n';
  });
}

}  // namespace hedge::detail
