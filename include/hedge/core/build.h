// Building a SurfaceMesh from index buffers (exporting one back to them: core/export.h).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "hedge/core/indexed_mesh.h"
#include "hedge/core/surface_mesh.h"

namespace hedge {

//! What to do with connectivity a half-edge mesh cannot hold.
enum class TopologyPolicy {
  //! Throw TopologyError naming the offending input vertices and faces.
  strict,
  //! Never drop a face silently: split non-manifold edges and vertices by duplicating vertices,
  //! re-orient faces where that makes the mesh orientable, and drop only degenerate faces
  //! (a repeated vertex, fewer than 3 corners). Every repair is counted in the BuildReport.
  repair,
};

enum class Weld {
  none,     //!< keep the input's vertices
  exact,    //!< merge vertices with bit-identical positions (+0 and -0 are equal)
  epsilon,  //!< merge vertices closer than weld_epsilon x bounding-box diagonal
};

struct BuildOptions {
  TopologyPolicy policy = TopologyPolicy::strict;
  Weld weld = Weld::none;
  //! Relative to the bounding-box diagonal; used with Weld::epsilon.
  double weld_epsilon = 1e-6;
  //! Carry the input's texcoords, normals and colours as corner properties "h:texcoord" (Vec2),
  //! "h:normal" (Vec3) and "h:color" (Color).
  bool corner_attributes = true;
};

//! What build() did. All counts are zero for clean input.
struct BuildReport {
  std::size_t welded_vertices = 0;        //!< input vertices merged into another by welding
  std::size_t degenerate_faces = 0;       //!< faces dropped: fewer than 3 distinct corners
  std::size_t repeated_corners = 0;       //!< consecutive repeated corners removed from kept faces
  std::size_t reoriented_faces = 0;       //!< faces whose winding was reversed
  std::size_t non_manifold_edges = 0;     //!< input edges with more than two faces, or two faces of
                                          //!< one direction that could not be re-oriented; cut apart
  std::size_t non_manifold_vertices = 0;  //!< vertices whose faces formed several fans
  std::size_t duplicated_vertices = 0;    //!< vertices added to split them
  std::size_t isolated_vertices = 0;      //!< vertices no face uses (kept; not a repair)

  //! input vertex -> mesh vertex (after welding; a split vertex maps to its first copy).
  std::vector<Index> vertex_map;
  //! input face -> mesh face, kInvalidIndex for a dropped face.
  std::vector<Index> face_map;
  //! mesh vertex -> input vertex it came from.
  std::vector<Index> vertex_origin;
  //! What the file reader kept but found suspect, each naming the file and line (or byte), e.g.
  //! a face of fewer than 3 corners that a truncated file leaves (read_mesh() fills it; the
  //! repair then drops that face and counts it in degenerate_faces).
  std::vector<std::string> warnings;

  //! Total number of repairs (isolated vertices and welding are not repairs).
  std::size_t repairs() const {
    return degenerate_faces + repeated_corners + reoriented_faces + non_manifold_edges +
           non_manifold_vertices;
  }
};

//! Builds a half-edge mesh from an indexed mesh in O(n) (bucketed twin matching, no hashing).
//! input.face_submeshes, when given, becomes the face property "f:submesh" of the faces kept.
//! \throw InvalidInputError on an index out of range, a non-finite position or colour, a size
//!        mismatch, or a face submesh outside [0, kMaxSubmesh].
//! \throw TopologyError under TopologyPolicy::strict when the input is not an oriented 2-manifold
//!        (with boundary) or has degenerate faces.
SurfaceMesh build(const IndexedMesh& input, const BuildOptions& options = {}, BuildReport* report = nullptr);

//! Same, from raw arrays: positions (#V) and triangle indices (3 #F).
SurfaceMesh build_triangles(std::span<const Vec3> positions, std::span<const std::uint32_t> triangles,
                            const BuildOptions& options = {}, BuildReport* report = nullptr);

//! Welds vertices of `positions`; returns old -> new indices and fills `unique` with the kept
//! positions in first-seen order. O(n) expected.
std::vector<Index> weld_positions(std::span<const Vec3> positions, Weld mode, double relative_epsilon,
                                  std::vector<Vec3>& unique);

}  // namespace hedge
