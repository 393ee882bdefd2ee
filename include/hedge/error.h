// Exceptions thrown by hedge. Every error that bad input can cause derives from hedge::Error.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace hedge {

//! Base class of every exception hedge throws on bad input or an illegal request.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! A file could not be read or written. what() names the path, the place and what was expected.
class IoError : public Error {
 public:
  //! \param line 1-based line for text formats, 0 when unknown or not applicable.
  //! \param byte_offset offset into the file for binary formats, -1 when not applicable.
  IoError(std::string path, std::uint64_t line, std::int64_t byte_offset, const std::string& message);

  const std::string& path() const noexcept { return path_; }
  std::uint64_t line() const noexcept { return line_; }
  std::int64_t byte_offset() const noexcept { return byte_offset_; }

 private:
  std::string path_;
  std::uint64_t line_;
  std::int64_t byte_offset_;
};

//! The connectivity cannot be represented (in strict mode) or an index is out of range.
//! vertices() and faces() name the offending input elements (input indices, not handles).
class TopologyError : public Error {
 public:
  TopologyError(const std::string& message, std::vector<std::uint32_t> vertices = {},
                std::vector<std::uint32_t> faces = {});
  const std::vector<std::uint32_t>& vertices() const noexcept { return vertices_; }
  const std::vector<std::uint32_t>& faces() const noexcept { return faces_; }

 private:
  std::vector<std::uint32_t> vertices_;
  std::vector<std::uint32_t> faces_;
};

//! An argument is invalid: a NaN coordinate, a handle of another mesh, a size mismatch.
class InvalidInputError : public Error {
 public:
  using Error::Error;
};

//! An amount of memory for a message: "512 bytes", "1.5 GiB".
std::string bytes_text(double bytes);

}  // namespace hedge
