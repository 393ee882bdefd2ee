// Measures of a mesh's geometry: face areas, the surface area, the bounding box and the enclosed
// volume. Computed in double from the float positions.
#pragma once

#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"

namespace hedge {

//! Newell's vector of face f: twice its area times its unit normal (for a planar polygon; the
//! best-fit plane's otherwise), oriented by its winding. O(face degree).
Vec3d area_vector(const SurfaceMesh& mesh, Face f);

//! The area of face f: half the length of its Newell vector, exact for planar polygons (a
//! non-planar polygon gets the area of its projection onto its best-fit plane). O(face degree).
double face_area(const SurfaceMesh& mesh, Face f);

//! The sum of the areas of the live faces. O(F).
double surface_area(const SurfaceMesh& mesh);

struct BoundingBox {
  Vec3 min{0, 0, 0}, max{0, 0, 0};
  //! True for the box of no vertex at all (min and max are then zero).
  bool empty = true;
  Vec3 size() const { return empty ? Vec3{0, 0, 0} : max - min; }
  Vec3 centre() const { return empty ? Vec3{0, 0, 0} : (min + max) * 0.5f; }
};

//! The axis-aligned box around the live vertices (isolated ones included). O(V).
BoundingBox bounding_box(const SurfaceMesh& mesh);

//! The signed volume the surface encloses: positive when the faces wind counter-clockwise seen from
//! outside (outward normals), negative for an inside-out surface, by the divergence theorem over the
//! faces' fan triangles. For several closed pieces, the sum of theirs. O(F).
//! \throw InvalidInputError if the mesh has a boundary (an open surface encloses no volume); the
//!   message says how many boundary half-edges it has.
double volume(const SurfaceMesh& mesh);

}  // namespace hedge
