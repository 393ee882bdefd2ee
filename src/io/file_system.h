// What the io layer asks of the operating system, declared once and implemented per platform:
// file_posix.cpp (Linux, macOS) and file_windows.cpp (Windows). read_file() and
// write_file_atomic() themselves are declared in hedge/io/io.h.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hedge::detail {

//! The characters that end a folder in a path: Windows takes both slashes.
#ifdef _WIN32
inline constexpr const char* kPathSeparators = "/\\";
#else
inline constexpr const char* kPathSeparators = "/";
#endif

//! What tells one file from another while it is read: its volume (device), its number there
//! (inode, file index) and its size.
struct FileIdentity {
  std::uint64_t device = 0;
  std::uint64_t number = 0;
  std::uint64_t size = 0;
};

//! The absolute path of `path` with `..` resolved and every symbolic link followed ('/' between
//! folders on every platform), or "" with errno set when it cannot be resolved.
std::string real_path(const std::string& path);

//! The identity of the regular file at `path` (links followed); false when there is none or it is
//! not a regular file.
bool identify_regular_file(const std::string& path, FileIdentity* out);

//! Reads the whole file at `path`, a resolved path, without following a final link, provided it is
//! still the file `expected` identifies; false when it changed or could not be read to its end.
bool read_if_unchanged(const std::string& path, const FileIdentity& expected,
                       std::vector<unsigned char>* out);

//! Temporary files of write_file_atomic(): "<dir>.<base>.hedge-tmp.<pid>.<n>", next to the target.
inline constexpr std::string_view temporary_tag = ".hedge-tmp.";
std::string temporary_name(const std::string& dir, const std::string& base, long pid, unsigned n);
//! The process id in `name` when it is a temporary of `base` as temporary_name() makes them, else 0.
long temporary_owner(std::string_view name, const std::string& base);

}  // namespace hedge::detail
