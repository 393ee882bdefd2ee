// Mass properties of a closed triangle mesh of uniform density, or of a thin shell of uniform
// thickness over any triangle mesh: what a rigid body needs.
#pragma once

#include <array>

#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"

namespace hedge {

struct MassProperties {
  double mass = 0;
  double volume = 0;
  Vec3d centre_of_mass;
  //! The inertia tensor about the centre of mass, in the mesh's axes, row-major 3x3 (symmetric):
  //! diagonal I_xx = integral of density (y^2 + z^2), off-diagonal I_xy = -integral of density x y.
  std::array<double, 9> inertia{};
  //! The eigenvalues of `inertia`, ascending.
  Vec3d principal_moments;
  //! Unit eigenvectors of `inertia`, principal_axes[i] for principal_moments[i]; a right-handed
  //! frame (axes[2] = cross(axes[0], axes[1])). For equal moments any orthonormal basis of their
  //! eigenspace is correct.
  std::array<Vec3d, 3> principal_axes{};
};

//! Mass, volume, centre of mass and inertia tensor of the solid a closed triangle mesh bounds, at
//! uniform `density` (mass per unit volume). Exact up to rounding: by the divergence theorem, each
//! face spans a signed tetrahedron with a reference point, whose integrals are closed forms
//! (Mirtich 1996; Eberly, "Polyhedral mass properties"). Computed in double relative to the
//! bounding-box centre, so a mesh far from the origin keeps its digits. Several closed pieces give
//! the properties of their union (when they do not overlap). O(F).
//! \pre faces wind counter-clockwise seen from outside (outward normals).
//! \throw InvalidInputError if `density` is not finite and positive; if the mesh has a boundary
//!   (naming how many boundary half-edges) or a face that is not a triangle (naming it); if the
//!   enclosed volume is not positive (an empty or inside-out mesh), giving the volume.
//! \throw InvalidInputError naming the first vertex whose position is not finite,
//!   before anything changes (require_finite_positions()).
MassProperties mass_properties(const SurfaceMesh& mesh, double density = 1.0);

//! Mass properties of a thin shell: the surface of a triangle mesh (open or closed) given a
//! uniform `thickness`, each triangle a slab of that thickness centred on it, at uniform `density`
//! (mass per unit volume). volume = area x thickness, mass = density x volume, the centre of mass is
//! the area centroid, and the inertia is that of the surface at surface density density x thickness
//! plus, per triangle, the slab's own term across it (mass x thickness^2 / 12 about the axes in
//! its plane). So a flat piece, whose surface alone has no extent along its normal, still has a
//! positive-definite inertia. Exact for the slabs up to rounding (their overlap at bends and the
//! bevels they lack are ignored: the shell is thin), computed in double relative to the
//! bounding-box centre. O(F).
//! \throw InvalidInputError if `density` or `thickness` is not finite and positive; if a face is
//!   not a triangle (naming it); if the total area is not positive.
//! \throw InvalidInputError naming the first vertex whose position is not finite,
//!   before anything changes (require_finite_positions()).
MassProperties shell_mass_properties(const SurfaceMesh& mesh, double density, double thickness);

}  // namespace hedge
