// The indexed form: what engines and files hold. Readers fill it, writers read it, and
// SurfaceMesh is built from it and exported to it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hedge/core/color.h"
#include "hedge/core/vec.h"
#include "hedge/error.h"

namespace hedge {

//! Something a file reader kept but found suspect (a face with fewer than 3 corners, as a file cut
//! in the middle of its last face line leaves), with where it is in the file.
struct ReadWarning {
  std::string path;
  std::uint64_t line = 0;         //!< 1-based line of a text file, 0 otherwise
  std::int64_t byte_offset = -1;  //!< offset into a binary file, -1 otherwise
  std::string message;
  //! The error this is under a strict policy.
  IoError error() const { return IoError(path, line, byte_offset, message); }
  //! "path:line: message" (text) or "path (byte N): message" (binary), as an IoError says it.
  std::string text() const { return error().what(); }
};

//! An indexed polygon mesh.
//!  - positions: #V positions.
//!  - indices: the corners of all faces, face after face, each a vertex index into positions.
//!  - face_sizes: #F corner counts; empty means every face is a triangle (indices.size() % 3 == 0).
//!  - texcoords / normals / colors: optional attribute pools; texcoord_indices / normal_indices /
//!    color_indices give one pool index per corner (same length as indices), as OBJ's v/vt/vn does.
//!    Empty when absent. Only glTF reads and writes colours; the other formats ignore them.
//!    A per-vertex attribute (PLY normals) is expressed with the corner index equal to the vertex index.
struct IndexedMesh {
  std::vector<Vec3> positions;
  std::vector<std::uint32_t> indices;
  std::vector<std::uint32_t> face_sizes;

  std::vector<Vec2> texcoords;
  std::vector<std::uint32_t> texcoord_indices;
  std::vector<Vec3> normals;
  std::vector<std::uint32_t> normal_indices;
  std::vector<Color> colors;
  std::vector<std::uint32_t> color_indices;

  //! Each face's submesh (the face property "f:submesh"), one per face in [0, kMaxSubmesh], or
  //! empty. to_indexed() fills it when the mesh has that property and build() turns it back into
  //! that property; write_obj() marks each run of faces of one submesh with "usemtl submesh_N";
  //! write_gltf() writes one primitive per submesh and read_gltf() fills it from the primitives'
  //! materials. The other writers and readers leave it out.
  std::vector<std::int32_t> face_submeshes;

  //! What the reader that made this mesh found suspect but kept (empty for meshes not read from a
  //! file). read_mesh() refuses them under the strict policy and reports them otherwise.
  std::vector<ReadWarning> warnings;

  //! Number of faces, whether or not face_sizes is used.
  std::size_t face_count() const { return face_sizes.empty() ? indices.size() / 3 : face_sizes.size(); }
  bool is_triangles() const { return face_sizes.empty(); }
};

}  // namespace hedge
