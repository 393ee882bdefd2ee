// Reading and writing mesh files: OBJ, OFF, PLY and STL, through the indexed form.
//
// Readers throw IoError (path, line or byte offset, what was expected) on malformed input and
// never trust a header's counts for allocation. Writers are atomic: they write a temporary file in
// the target's folder and rename it over the target, so a failed write leaves nothing behind.
#pragma once

#include <string>
#include <string_view>

#include "hedge/core/build.h"
#include "hedge/core/indexed_mesh.h"
#include "hedge/core/surface_mesh.h"

namespace hedge::io {

enum class Format { obj, off, ply, stl };

//! The format for a path's extension (case-insensitive). \throw IoError for an unknown one.
Format format_from_path(const std::string& path);

struct WriteOptions {
  //! PLY and STL: binary (little endian) when true, ASCII when false. Ignored for OBJ and OFF.
  bool binary = true;
  //! Significant digits of ASCII coordinates (9 keeps every float exact).
  int precision = 9;
};

// Per-format readers. `name` is used in error messages. Parsing works on the whole file in memory.
IndexedMesh read_obj(std::string_view data, const std::string& name = {});
IndexedMesh read_off(std::string_view data, const std::string& name = {});
IndexedMesh read_ply(std::string_view data, const std::string& name = {});
IndexedMesh read_stl(std::string_view data, const std::string& name = {});
IndexedMesh read_indexed(std::string_view data, Format format, const std::string& name = {});

// Per-format writers into a string (the atomic file writers wrap these).
std::string write_obj(const IndexedMesh& mesh, const WriteOptions& options = {});
std::string write_off(const IndexedMesh& mesh, const WriteOptions& options = {});
std::string write_ply(const IndexedMesh& mesh, const WriteOptions& options = {});
std::string write_stl(const IndexedMesh& mesh, const WriteOptions& options = {});
std::string write_indexed(const IndexedMesh& mesh, Format format, const WriteOptions& options = {});

//! Reads a whole file. \throw IoError if it cannot be opened or read.
std::string read_file(const std::string& path);
//! Writes `bytes` to `path` atomically (temporary file in the same folder, then rename).
void write_file_atomic(const std::string& path, std::string_view bytes);

//! Reads a file of any supported format into the indexed form (format from the extension).
IndexedMesh read_indexed_file(const std::string& path);
//! Writes the indexed form to a file (format from the extension), atomically.
void write_indexed_file(const IndexedMesh& mesh, const std::string& path, const WriteOptions& options = {});

//! Build options for loading files: repair policy, and exact welding for STL (which stores no
//! connectivity). Other formats keep the file's vertices.
BuildOptions default_build_options(Format format);

//! Reads and builds a SurfaceMesh. Uses default_build_options(format) unless options are given.
SurfaceMesh read_mesh(const std::string& path, BuildReport* report = nullptr);
SurfaceMesh read_mesh(const std::string& path, const BuildOptions& options, BuildReport* report = nullptr);
//! Exports (triangulating for STL) and writes atomically.
void write_mesh(const SurfaceMesh& mesh, const std::string& path, const WriteOptions& options = {});

}  // namespace hedge::io
