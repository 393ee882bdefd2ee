// Files: format dispatch and the SurfaceMesh entry points. Reading and atomic writing, which speak to
// the operating system, are in file_posix.cpp and file_windows.cpp (file_system.h).

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <string>
#include <string_view>
#include <utility>

#include "file_system.h"
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

}  // namespace

FileFormat format_from_path(const std::string& path) {
  if (path.empty())
    throw IoError(
        path, 0, -1,
        "no file name: the path is empty (expected one ending in .obj, .off, .ply, .stl, .gltf or .glb)");
  const std::size_t slash = path.find_last_of(detail::kPathSeparators);
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
  using Writer = std::string (*)(const IndexedMesh&, const WriteOptions&);
  static constexpr std::pair<FileFormat, Writer> kWriters[] = {
      {FileFormat::obj, write_obj}, {FileFormat::off, write_off},   {FileFormat::ply, write_ply},
      {FileFormat::stl, write_stl}, {FileFormat::gltf, write_gltf}, {FileFormat::glb, write_glb}};
  for (const auto& [f, write] : kWriters)
    if (f == format) return write(mesh, options);
  throw InvalidInputError("unknown format");
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
  return build_read(read_indexed_file(path, read_options), options, report);
}

SurfaceMesh build_read(const IndexedMesh& in, const BuildOptions& options, BuildReport* report) {
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
  if (format == FileFormat::gltf || format == FileFormat::glb)
    export_options.triangulation = Triangulation::ear;
  // The export renumbers vertices when the mesh has garbage: name the mesh's own vertex.
  require_finite_positions(mesh, "write_mesh");
  write_file_atomic(path, write_indexed(to_indexed(mesh, export_options), format, options));
}

namespace detail {

std::string temporary_name(const std::string& dir, const std::string& base, long pid, unsigned n) {
  return dir + "." + base + std::string(temporary_tag) + std::to_string(pid) + "." + std::to_string(n);
}

long temporary_owner(std::string_view name, const std::string& base) {
  const std::string prefix = "." + base + std::string(temporary_tag);
  if (name.substr(0, prefix.size()) != prefix) return 0;
  name.remove_prefix(prefix.size());
  auto digits = [&](long& value) {
    const auto [end, ec] = std::from_chars(name.data(), name.data() + name.size(), value);
    if (ec != std::errc() || end == name.data()) return false;
    name.remove_prefix(static_cast<std::size_t>(end - name.data()));
    return true;
  };
  long pid = 0, n = 0;
  if (!digits(pid) || name.empty() || name.front() != '.') return 0;
  name.remove_prefix(1);
  if (!digits(n) || !name.empty() || n < 0) return 0;
  return pid > 0 && pid <= std::numeric_limits<std::int32_t>::max() ? pid : 0;
}

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
  auto finite = [](std::initializer_list<float> values, const char* what, std::size_t i) {
    for (float x : values)
      if (!std::isfinite(x)) {
        std::string text = std::string("indexed mesh: ") + what + " " + std::to_string(i) + " (";
        char number[32];
        const char* separator = "";
        for (float v : values) {
          std::snprintf(number, sizeof number, "%s%g", separator, double(v));
          text += number;
          separator = ", ";
        }
        throw InvalidInputError(text + ") is not finite");
      }
  };
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3& p = mesh.positions[i];
    finite({p.x, p.y, p.z}, "position", i);
  }
  for (std::size_t i = 0; i < mesh.texcoords.size(); ++i)
    finite({mesh.texcoords[i].x, mesh.texcoords[i].y}, "texture coordinate", i);
  for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
    const Vec3& n = mesh.normals[i];
    finite({n.x, n.y, n.z}, "normal", i);
  }
  for (std::size_t i = 0; i < mesh.colors.size(); ++i) {
    const Color& c = mesh.colors[i];
    finite({c.r, c.g, c.b, c.a}, "color", i);
  }
}

}  // namespace detail

}  // namespace hedge
