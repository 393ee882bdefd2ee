// Files: whole-file reading, atomic writing, format dispatch, and the SurfaceMesh entry points.

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>

#include "hedge/core/export.h"
#include "hedge/io/io.h"
#include "parse_util.h"

namespace hedge {

namespace {

std::string lower(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return s;
}

std::string errno_text(int err) { return std::strerror(err); }

// Closes a descriptor on every exit path.
class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }
  //! Closes now and reports close()'s error, which for a written file can be a deferred write error.
  int close() {
    const int r = ::close(fd_);
    fd_ = -1;
    return r;
  }

 private:
  int fd_;
};

}  // namespace

FileFormat format_from_path(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
    const std::string ext = lower(path.substr(dot + 1));
    if (ext == "obj") return FileFormat::obj;
    if (ext == "off") return FileFormat::off;
    if (ext == "ply") return FileFormat::ply;
    if (ext == "stl") return FileFormat::stl;
    if (ext == "gltf") return FileFormat::gltf;
    if (ext == "glb") return FileFormat::glb;
  }
  throw IoError(path, 0, -1, "unknown file extension (expected .obj, .off, .ply, .stl, .gltf or .glb)");
}

IndexedMesh read_indexed(std::string_view data, FileFormat format, const std::string& name,
                         const ReadOptions& options) {
  switch (format) {
    case FileFormat::obj:
      return read_obj(data, name);
    case FileFormat::off:
      return read_off(data, name);
    case FileFormat::ply:
      return read_ply(data, name);
    case FileFormat::stl:
      return read_stl(data, name);
    case FileFormat::gltf:
    case FileFormat::glb:
      return read_gltf(data, name, options);
  }
  throw IoError(name, 0, -1, "unknown format");
}

std::string write_indexed(const IndexedMesh& mesh, FileFormat format, const WriteOptions& options) {
  switch (format) {
    case FileFormat::obj:
      return write_obj(mesh, options);
    case FileFormat::off:
      return write_off(mesh, options);
    case FileFormat::ply:
      return write_ply(mesh, options);
    case FileFormat::stl:
      return write_stl(mesh, options);
    case FileFormat::gltf:
      return write_gltf(mesh, options);
    case FileFormat::glb:
      return write_glb(mesh, options);
  }
  throw InvalidInputError("unknown format");
}

std::string read_file(const std::string& path) {
  Fd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (fd.get() < 0) throw IoError(path, 0, -1, "cannot open: " + errno_text(errno));
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) throw IoError(path, 0, -1, "cannot stat: " + errno_text(errno));
  if (S_ISDIR(st.st_mode)) throw IoError(path, 0, -1, "cannot read: it is a directory");
  std::string data;
  // The size is only a hint (pipes report 0, a file may grow): read until end of file. One byte
  // more than the size lets the first read() reach the end and the second one confirm it.
  data.resize(S_ISREG(st.st_mode) && st.st_size > 0 ? static_cast<std::size_t>(st.st_size) + 1 : 65536);
  std::size_t used = 0;
  for (;;) {
    if (used == data.size()) data.resize(2 * data.size());
    const ssize_t n = ::read(fd.get(), data.data() + used, data.size() - used);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw IoError(path, 0, static_cast<std::int64_t>(used), "read error: " + errno_text(errno));
    }
    if (n == 0) break;
    used += static_cast<std::size_t>(n);
  }
  data.resize(used);
  return data;
}

void write_file_atomic(const std::string& path, std::string_view bytes) {
  if (path.empty() || path.back() == '/') throw IoError(path, 0, -1, "cannot write: not a file name");
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string(".") : path.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::string prefix = (slash == std::string::npos ? std::string() : dir) + "." + base + ".tmp-";

  // A unique name in the target's folder (rename is atomic only within one file system). O_EXCL
  // makes a clash with another writer fail instead of sharing the file; then another name is tried.
  std::string temp;
  int raw_fd = -1;
  int err = 0;
  for (int attempt = 0; attempt < 32 && raw_fd < 0; ++attempt) {
    const auto tick = static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
    const std::uint64_t salt = tick * 0x9E3779B97F4A7C15ull ^ (static_cast<std::uint64_t>(::getpid()) << 32) ^
                               static_cast<std::uint64_t>(attempt);
    temp = prefix + std::to_string(salt % 1000000000000ull);
    raw_fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    err = errno;
    if (raw_fd < 0 && err != EEXIST) break;
  }
  if (raw_fd < 0)
    throw IoError(path, 0, -1, "cannot create a temporary file in '" + dir + "': " + errno_text(err));
  Fd fd(raw_fd);

  auto fail = [&](const std::string& what, int e) {
    if (fd.get() >= 0) fd.close();
    ::unlink(temp.c_str());
    throw IoError(path, 0, -1, what + ": " + errno_text(e));
  };

  // Replacing a file keeps its permissions.
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) ::fchmod(fd.get(), st.st_mode & 07777);

  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd.get(), p, std::min<std::size_t>(left, std::size_t{1} << 30));
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write error", errno);
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  // The data must be on disk before the rename makes it visible, or a crash could leave an empty
  // file under the target's name.
  if (::fsync(fd.get()) != 0 && errno != EINVAL) fail("cannot flush", errno);
  if (fd.close() != 0) fail("write error on close", errno);
  if (::rename(temp.c_str(), path.c_str()) != 0) fail("cannot replace the target", errno);
}

std::uint64_t read_budget(const ReadOptions& options, std::uint64_t input_bytes) {
  if (options.max_memory != 0) return options.max_memory;
  constexpr std::uint64_t kFactor = 64;
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max();
  return input_bytes > (limit - kDefaultReadMemoryFloor) / kFactor ? limit
                                                                     : kFactor * input_bytes + kDefaultReadMemoryFloor;
}

IndexedMesh read_indexed_file(const std::string& path) {
  ReadOptions options;
  options.external_buffers = true;
  return read_indexed_file(path, options);
}

IndexedMesh read_indexed_file(const std::string& path, const ReadOptions& options) {
  const FileFormat format = format_from_path(path);
  return read_indexed(read_file(path), format, path, options);
}

void write_indexed_file(const IndexedMesh& mesh, const std::string& path, const WriteOptions& options) {
  const FileFormat format = format_from_path(path);
  write_file_atomic(path, write_indexed(mesh, format, options));
}

BuildOptions default_build_options(FileFormat format) {
  BuildOptions options;
  options.policy = TopologyPolicy::repair;
  const bool welds = format == FileFormat::stl || format == FileFormat::gltf || format == FileFormat::glb;
  options.weld = welds ? Weld::exact : Weld::none;
  return options;
}

SurfaceMesh read_mesh(const std::string& path, BuildReport* report) {
  return read_mesh(path, default_build_options(format_from_path(path)), report);
}

SurfaceMesh read_mesh(const std::string& path, const BuildOptions& options, BuildReport* report) {
  ReadOptions read_options;
  read_options.external_buffers = true;
  return read_mesh(path, options, read_options, report);
}

SurfaceMesh read_mesh(const std::string& path, const BuildOptions& options, const ReadOptions& read_options,
                      BuildReport* report) {
  const IndexedMesh in = read_indexed_file(path, read_options);
  if (!in.warnings.empty() && options.policy == TopologyPolicy::strict) throw in.warnings.front().error();
  SurfaceMesh mesh = build(in, options, report);
  if (report)
    for (const ReadWarning& w : in.warnings) report->warnings.push_back(w.text());
  return mesh;
}

void write_mesh(const SurfaceMesh& mesh, const std::string& path, const WriteOptions& options) {
  const FileFormat format = format_from_path(path);
  ExportOptions export_options;
  // STL stores triangles only.
  if (format == FileFormat::stl) export_options.triangulation = Triangulation::fan;
  // glTF stores triangles only; ear clipping keeps concave polygons inside their outline.
  if (format == FileFormat::gltf || format == FileFormat::glb) export_options.triangulation = Triangulation::ear;
  write_file_atomic(path, write_indexed(to_indexed(mesh, export_options), format, options));
}

namespace detail {

void check_writable(const IndexedMesh& mesh) {
  std::uint64_t corners = 0;
  if (mesh.face_sizes.empty()) {
    if (mesh.indices.size() % 3 != 0)
      throw InvalidInputError("indexed mesh: " + std::to_string(mesh.indices.size()) +
                              " indices is not a multiple of 3 and face_sizes is empty");
    corners = mesh.indices.size();
  } else {
    for (std::size_t f = 0; f < mesh.face_sizes.size(); ++f) {
      if (mesh.face_sizes[f] == 0)
        throw InvalidInputError("indexed mesh: face " + std::to_string(f) + " has no corners");
      corners += mesh.face_sizes[f];
    }
  }
  if (corners != mesh.indices.size())
    throw InvalidInputError("indexed mesh: face sizes add up to " + std::to_string(corners) +
                            " corners, but there are " + std::to_string(mesh.indices.size()) + " indices");
  auto check = [&](const std::vector<std::uint32_t>& idx, std::size_t pool, const char* what, bool optional) {
    if (optional && idx.empty()) return;
    if (idx.size() != mesh.indices.size())
      throw InvalidInputError(std::string("indexed mesh: ") + what + " indices have " +
                              std::to_string(idx.size()) + " entries, expected one per corner (" +
                              std::to_string(mesh.indices.size()) + ")");
    for (std::size_t c = 0; c < idx.size(); ++c)
      if (idx[c] >= pool)
        throw InvalidInputError(std::string("indexed mesh: corner ") + std::to_string(c) + " has " + what +
                                " index " + std::to_string(idx[c]) + ", out of range (" +
                                std::to_string(pool) + ")");
  };
  check(mesh.indices, mesh.positions.size(), "vertex", false);
  check(mesh.texcoord_indices, mesh.texcoords.size(), "texture coordinate", true);
  check(mesh.normal_indices, mesh.normals.size(), "normal", true);
  check(mesh.color_indices, mesh.colors.size(), "color", true);
}

}  // namespace detail

}  // namespace hedge
