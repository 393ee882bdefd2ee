// Reading and writing mesh files: OBJ, OFF, PLY, STL and glTF 2.0 (.gltf, .glb), through the
// indexed form.
//
// Readers throw IoError (path, line or byte offset, what was expected) on malformed input and
// never trust a header's counts for allocation. Writers are atomic: they write a temporary file in
// the target's folder and rename it over the target, so a failed or killed write leaves nothing
// behind (see write_file_atomic()).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "hedge/core/build.h"
#include "hedge/core/indexed_mesh.h"
#include "hedge/core/surface_mesh.h"

namespace hedge {

//! gltf and glb are both read by read_gltf(), which tells them apart by their first bytes; they
//! differ in what is written: JSON with the buffer embedded, or the binary container.
enum class FileFormat { obj, off, ply, stl, gltf, glb };

//! The format for a path's extension (case-insensitive). \throw IoError for an unknown one.
FileFormat format_from_path(const std::string& path);

struct WriteOptions {
  //! PLY and STL: binary (little endian) when true, ASCII when false. Ignored for OBJ and OFF, and
  //! for glTF, whose extension (FileFormat::gltf or glb) chooses.
  bool binary = true;
  //! Significant digits of ASCII coordinates. 9 or more writes the shortest text that reads back to
  //! the same float (so every float survives a round trip); fewer rounds to that many digits.
  int precision = 9;
};

//! What a reader may do for a file that comes from a stranger. The default is the safe choice for
//! bytes of unknown origin: no file but the one given is opened, and memory stays within the default
//! budget. read_indexed_file() and read_mesh() without options read glTF buffers beside the file.
struct ReadOptions {
  //! glTF buffers stored in separate files (a `uri` that is not a data URI). When true they are read
  //! only from the folder of the .gltf named by `name` and its subfolders: the uri must be a
  //! relative path without a scheme, and after `%` escapes, `..` and symbolic links are resolved it
  //! must name a regular file inside that folder whose size is the buffer's byteLength (checked
  //! before reading). When false, any such buffer is an error.
  bool external_buffers = false;
  //! The most memory, in bytes, a glTF reader may allocate for what the file describes (its JSON,
  //! nodes, primitives, vertices, corners), estimated and checked before anything is allocated.
  //! 0 is the default budget: 64 times the input's size (the file and its external buffers) plus
  //! kDefaultReadMemoryFloor, enough for any file whose meshes are stored rather than instanced.
  //! Raise it for a trusted file that places one mesh many times.
  std::uint64_t max_memory = 0;
};

//! The fixed part of the default read budget (see ReadOptions::max_memory): 64 MiB.
inline constexpr std::uint64_t kDefaultReadMemoryFloor = std::uint64_t{64} << 20;
//! The deepest nesting of arrays and objects a glTF's JSON may have. Deeper nesting is refused
//! before the JSON is parsed (glTF's own structure needs about 8 levels).
inline constexpr int kMaxJsonDepth = 64;

//! The read budget for an input of `input_bytes` bytes under `options` (see ReadOptions::max_memory).
std::uint64_t read_budget(const ReadOptions& options, std::uint64_t input_bytes);

// Per-format readers. `name` is used in error messages. Parsing works on the whole file in memory.
//
// Every reader returns a mesh whose indices are all in range and whose coordinates are all finite,
// with face_sizes empty when every face is a triangle. A face of 1 or 2 corners (what a file cut in
// the middle of a face line leaves) is kept and noted in IndexedMesh::warnings with its line (text)
// or byte offset (binary); read_mesh() refuses it under the strict policy, and the repair drops it. It costs
// O(file size) time and allocates no more than the file's size can justify, whatever counts a header claims.
// \throw IoError on malformed input: what() is "name:line: message" for text ("name (byte N):
// message" for binary data) and says what was expected and what was found. Elements are numbered
// from 0 in messages, as in the IndexedMesh ("face 12" is the 13th face).

//! OBJ: v (w and vertex colours ignored), vt, vn, f in the v, v/vt, v//vn, v/vt/vn forms with
//! negative (relative) indices, polygons, comments, backslash continuations; o, g, s, usemtl,
//! mtllib, l, p and the other statements of the specification are ignored, an unknown keyword is
//! an error. Texture coordinates (normals) are kept only when every corner of every face has one;
//! if only some corners do, the attribute is dropped without an error.
IndexedMesh read_obj(std::string_view data, const std::string& name = {});
//! OFF, COFF, NOFF, CNOFF, STOFF... ('#' comments, counts possibly on the header line, optional
//! header keyword). Vertex normals and colours and face colours are skipped. One record per line.
IndexedMesh read_off(std::string_view data, const std::string& name = {});
//! PLY: ascii, binary_little_endian, binary_big_endian, any element order. Reads vertex x y z (any
//! numeric type), nx ny nz and u v (or s t, texture_u texture_v) as per-vertex attributes (corner
//! index arrays equal to the vertex indices), the face element's vertex_indices / vertex_index
//! list, and tristrips (-1 restarts; every other triangle flipped; triangles with a repeated index
//! dropped). Other elements and properties, lists included, are skipped.
IndexedMesh read_ply(std::string_view data, const std::string& name = {});
//! STL, ASCII or binary: the triangle soup as stored (3 vertices per triangle, no welding; see
//! default_build_options). A file whose size is 84 + 50 n, n being the count at byte 80, is binary
//! even when its header starts with "solid".
IndexedMesh read_stl(std::string_view data, const std::string& name = {});
//! glTF 2.0, JSON (.gltf) or binary (.glb, recognised by its "glTF" magic), with its buffers in
//! the GLB chunk, in base64 data URIs (application/octet-stream or application/gltf-buffer) or,
//! when options.external_buffers allows, in files beside it (in the folder of `name` or below).
//!  - What is read: the default scene (else scene 0) walked from its root nodes, each node's mesh
//!    placed by the node's world transform (matrix or translation/rotation/scale; a mirroring one
//!    reverses the winding; an identity one leaves positions bit for bit). A file without scenes
//!    gives every mesh once, untransformed. All primitives of all placed meshes are merged into one
//!    mesh, in that order, vertices kept apart (default_build_options() welds equal positions, so
//!    seams become corner attributes). Primitives of one node that share their attribute accessors
//!    (several materials over one vertex set) share their vertices. When a primitive has a material,
//!    each face's submesh (IndexedMesh::face_submeshes) is its primitive's material number (0 for a
//!    primitive without one, kMaxSubmesh for a larger one), as write_gltf() writes them.
//!  - Attributes: POSITION (float VEC3, required), NORMAL (float VEC3), TEXCOORD_0 (float or
//!    normalized unsigned byte/short VEC2) and COLOR_0 (float or normalized unsigned byte/short,
//!    VEC3 read with alpha 1, or VEC4) as per-vertex attributes, kept only when every merged
//!    primitive has them; v is flipped (v' = 1 - v) from glTF's top-left texture origin to hedge's
//!    bottom-left one (OBJ's). COLOR_1.., TEXCOORD_1.., tangents, skins, morph targets, the
//!    materials' content and images are not read (images are never decoded).
//!  - Modes TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN (strip and fan triangles with a repeated
//!    index dropped). A POINTS or LINES primitive is skipped with a ReadWarning naming it.
//!  - Indices u8, u16 or u32, or none (vertices in order). Sparse accessors and byteStride are
//!    handled. KHR_draco_mesh_compression and KHR_mesh_quantization data is refused.
//! \throw IoError "name: where: what" for bad JSON or GLB framing, a missing POSITION, a reference
//!        to a scene, node, mesh, accessor, bufferView or buffer that does not exist, an accessor
//!        whose bytes are outside its bufferView or buffer, a component type glTF does not allow
//!        for the attribute, an index out of range, a non-finite value, a node reached twice (glTF
//!        nodes form trees), a negative index, offset, count or mode, JSON nested deeper than
//!        kMaxJsonDepth, more memory than the read budget (ReadOptions::max_memory; the message says
//!        how much the file asks for), and an external buffer that is turned off, outside the
//!        file's folder, not a regular file or of the wrong size (the message never quotes such a
//!        file's content or size); e.g.
//!        "m.gltf: mesh 0 primitive 0 indices: accessor 3: index 9 (element 4) is out of range".
//!        Cost: O(file size) time; memory within the budget.
IndexedMesh read_gltf(std::string_view data, const std::string& name = {}, const ReadOptions& options = {});
//! Any format's reader; `options` matter for glTF only (the other formats open no other file and
//! allocate at most a small constant times the data's size).
IndexedMesh read_indexed(std::string_view data, FileFormat format, const std::string& name = {},
                         const ReadOptions& options = {});

// Per-format writers into a string (the atomic file writers wrap these). O(mesh size).
// Coordinates are written so that they read back bit for bit (see WriteOptions::precision).
// \throw InvalidInputError when the mesh is inconsistent: face sizes not adding up to the index
//        count, a face without corners, an index out of its pool, attribute index arrays of the
//        wrong length, or a position, texture coordinate, normal or colour that is not finite
//        (the readers refuse those, so the file could not be read back). Nothing is written then.

//! OBJ: v, then vt and vn when the mesh has those corner attributes, and f with v/vt/vn corners.
std::string write_obj(const IndexedMesh& mesh, const WriteOptions& options = {});
//! OFF: positions and polygons; attributes are not written.
std::string write_off(const IndexedMesh& mesh, const WriteOptions& options = {});
//! PLY with float x y z; nx ny nz (u v) only when every vertex's corners agree on one normal
//! (texture coordinate), since PLY stores them per vertex. Polygons as a uchar (uint above 255
//! corners) list of uint.
std::string write_ply(const IndexedMesh& mesh, const WriteOptions& options = {});
//! STL: polygons fanned into triangles, facet normals computed (zero for a degenerate triangle).
//! The binary header never starts with "solid".
std::string write_stl(const IndexedMesh& mesh, const WriteOptions& options = {});
//! glTF 2.0 JSON with the one buffer embedded as a base64 data URI (one self-contained file), or
//! the binary .glb container. One mesh on one node of one scene, of one TRIANGLES primitive, or,
//! when the mesh has face_submeshes, one per submesh in increasing order (faces in order within
//! it), all sharing the vertex accessors, with material N (named "submesh_N"; materials 0 to the
//! largest submesh are written) for submesh N:
//! POSITION (float, with the min/max the specification requires), NORMAL, TEXCOORD_0 and COLOR_0
//! (float VEC4) when the mesh has them (v flipped as read_gltf() says), u16 indices when the vertex
//! count allows, else u32. Polygons are fanned from their first corner. A mesh vertex splits into
//! one glTF vertex per distinct (texcoord, normal, colour) of its corners (seams, hard edges); vertex v keeps
//! number v with its first corner's attributes and the split copies follow, so positions read back in order.
//! A vertex no face uses is written with zero attributes. A mesh without faces gives a file without scenes or
//! meshes.
std::string write_gltf(const IndexedMesh& mesh, const WriteOptions& options = {});
std::string write_glb(const IndexedMesh& mesh, const WriteOptions& options = {});
std::string write_indexed(const IndexedMesh& mesh, FileFormat format, const WriteOptions& options = {});

//! Reads a whole file. Paths are UTF-8 on every system (on Windows they are converted to UTF-16 and
//! may use either slash). \throw IoError if it cannot be opened or read.
std::string read_file(const std::string& path);
//! Writes `bytes` to `path` atomically: the file holds its old bytes or the new ones, never a mix,
//! and a write that fails or is killed leaves the old file as it was.
//! - The bytes go to a temporary file in the target's folder, flushed to disk before the file takes
//!   the target's name. On Linux it is an unnamed file (O_TMPFILE), which vanishes with a killed
//!   process: with no target it is linked straight to the target's name; otherwise it is linked to
//!   a temporary name and at once renamed over the target. Where the file system has no unnamed
//!   files it is `.<name>.hedge-tmp.<pid>.<n>` from the start, which a killed write leaves behind:
//!   every write of `<name>` first removes those whose process no longer exists.
//! - A symbolic link is followed, through the whole chain (a relative link from its own folder),
//!   and the file it leads to is replaced in that file's folder, as editors do: the link stays a
//!   link. A dangling link gets the file it points to created.
//! - A replaced file keeps its permission bits, and its owner and group where this process may
//!   set them (as root, or a group the process belongs to).
//! - On Windows the temporary is always named (Windows has no unnamed files), flushed, and moved
//!   over the target in one step (MoveFileExW); a symbolic link as the target is replaced itself,
//!   not followed; a file with the read-only attribute is refused; owners are not copied.
//! \throw IoError naming `path` and the reason, with nothing written and the target untouched, when
//!        the target (after links) is a directory, a FIFO, a device or a socket; when it has no
//!        write permission bit at all (mode & 0222 == 0), even for root: a read-only file is not
//!        replaced; when links loop; and, with the system's reason, when the folder is missing or
//!        not writable or a write fails.
void write_file_atomic(const std::string& path, std::string_view bytes);

//! Reads a file of any supported format into the indexed form (format from the extension). Without
//! options, glTF buffers beside the file are read (ReadOptions::external_buffers = true).
IndexedMesh read_indexed_file(const std::string& path);
IndexedMesh read_indexed_file(const std::string& path, const ReadOptions& options);
//! Writes the indexed form to a file (format from the extension), atomically.
void write_indexed_file(const IndexedMesh& mesh, const std::string& path, const WriteOptions& options = {});

//! Build options for loading files: repair policy, and exact welding for STL (which stores no
//! connectivity) and glTF (which splits vertices at seams). Other formats keep the file's vertices.
BuildOptions default_build_options(FileFormat format);

//! Builds what a reader returned: the reader's warnings (IndexedMesh::warnings) are an IoError
//! naming the file and line under TopologyPolicy::strict, and go to BuildReport::warnings
//! otherwise. read_mesh() is read_indexed_file() followed by this.
SurfaceMesh build_read(const IndexedMesh& in, const BuildOptions& options, BuildReport* report = nullptr);

//! Reads and builds a SurfaceMesh. Uses default_build_options(format) unless options are given.
//! What the reader found suspect (IndexedMesh::warnings) is an IoError naming the file and line
//! under TopologyPolicy::strict, and goes to BuildReport::warnings otherwise.
SurfaceMesh read_mesh(const std::string& path, BuildReport* report = nullptr);
SurfaceMesh read_mesh(const std::string& path, const BuildOptions& options, BuildReport* report = nullptr);
SurfaceMesh read_mesh(const std::string& path, const BuildOptions& options, const ReadOptions& read_options,
                      BuildReport* report = nullptr);
//! Exports (triangulating for STL, and by ear clipping for glTF) and writes atomically.
//! \throw InvalidInputError naming the first vertex whose position is not finite,
//!   before anything changes (require_finite_positions()).
void write_mesh(const SurfaceMesh& mesh, const std::string& path, const WriteOptions& options = {});

namespace detail {
//! For tests: when on, write_file_atomic() uses named temporary files, as on a file system without
//! unnamed ones. Returns the previous setting (always true on Windows, where every temporary is
//! named).
bool force_named_temporary_files(bool on);
}  // namespace detail

}  // namespace hedge
