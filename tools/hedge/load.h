// Loading a mesh file with the command line's repair and welding choices.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "hedge/core/build.h"
#include "hedge/core/surface_mesh.h"
#include "hedge/io/io.h"
#include "memory_budget.h"

namespace hedge::cli {

struct LoadOptions {
  bool strict = false;               //!< TopologyPolicy::strict instead of repairing
  std::string weld;                  //!< "none", "exact", "epsilon"; empty keeps the format's default
  double weld_eps = -1.0;            //!< relative welding tolerance; negative when not given
  bool no_external_buffers = false;  //!< glTF: refuse buffers stored in separate files
  //! --max-memory: the budget of reading a glTF (else the reader's own default, relative to the
  //! file's size) and of the work a command's numbers size (else the memory available).
  MemoryBudget memory;
};

//! Adds --strict, --weld, --weld-eps, --no-external-buffers and --max-memory to a subcommand.
void add_load_options(CLI::App& command, LoadOptions& options);

//! The build options for `format` after applying the command line's choices. --weld-eps without
//! --weld implies --weld epsilon.
BuildOptions build_options(FileFormat format, const LoadOptions& options);

struct LoadedMesh {
  SurfaceMesh mesh;
  BuildReport report;
  FileFormat format = FileFormat::obj;
};

//! The read options of the command line: external glTF buffers beside the file unless
//! --no-external-buffers, and --max-memory as the read budget when given.
ReadOptions read_options(const LoadOptions& options);

//! Reads and builds `path`. Errors that do not name the file already (topology, invalid input) are
//! rethrown with "path: " in front, keeping their type. The reader's warnings (a face of fewer
//! than 3 corners, ...) go to stderr as "hedge: warning: file:line: ..." lines.
LoadedMesh load_mesh(const std::string& path, const LoadOptions& options);

//! Writes `mesh` to `path` (format from the extension; PLY and STL binary unless `ascii`),
//! creating missing folders; the file is replaced atomically.
void save_mesh(const SurfaceMesh& mesh, const std::string& path, bool ascii);

//! Lower-case name of a format ("obj", "off", "ply", "stl", "gltf", "glb").
const char* format_name(FileFormat format);

}  // namespace hedge::cli
