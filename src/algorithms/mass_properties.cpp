#include "hedge/algorithms/mass_properties.h"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <string>

#include "format.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/error.h"

namespace hedge {
namespace {

using detail::number;

void check_positive(double value, const char* what, const char* caller) {
  if (!std::isfinite(value) || value <= 0)
    throw InvalidInputError(std::string(caller) + ": " + what + " must be finite and positive, got " +
                            number(value));
}

void check_triangles(const SurfaceMesh& mesh, const char* caller) {
  for (Face f : mesh.faces())
    if (mesh.valence(f) != 3)
      throw InvalidInputError(std::string(caller) + ": face " + std::to_string(f.idx()) + " has " +
                              std::to_string(mesh.valence(f)) + " corners, not 3 (triangulate first)");
  require_finite_positions(mesh, caller);
}

void check_input(const SurfaceMesh& mesh, double density) {
  check_positive(density, "density", "mass_properties");
  std::size_t boundary = 0;
  for (Halfedge h : mesh.halfedges())
    if (mesh.is_boundary(h)) ++boundary;
  if (boundary > 0)
    throw InvalidInputError("mass_properties: the mesh is not closed (" + std::to_string(boundary) +
                            " boundary half-edges)");
  check_triangles(mesh, "mass_properties");
}

//! Fills the inertia tensor and its principal frame from `cov`, the second moments of the mass
//! about the centre of mass: I = tr(C) 1 - C.
void set_inertia(MassProperties& m, const double (&cov)[3][3]) {
  const double trace = cov[0][0] + cov[1][1] + cov[2][2];
  Eigen::Matrix3d inertia;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      const double value = (i == j ? trace : 0.0) - cov[i][j];
      inertia(Eigen::Index(i), Eigen::Index(j)) = value;
      m.inertia[3 * i + j] = value;
    }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inertia);
  Eigen::Matrix3d axes = eigen.eigenvectors();
  axes.col(2) = axes.col(0).cross(axes.col(1));
  for (Eigen::Index k = 0; k < 3; ++k) {
    m.principal_moments[std::size_t(k)] = eigen.eigenvalues()(k);
    m.principal_axes[std::size_t(k)] = {axes(0, k), axes(1, k), axes(2, k)};
  }
}

Vec3d reference_point(const SurfaceMesh& mesh) {
  const BoundingBox box = bounding_box(mesh);
  return (to_double(box.min) + to_double(box.max)) * 0.5;
}

}  // namespace

MassProperties mass_properties(const SurfaceMesh& mesh, double density) {
  check_input(mesh, density);
  const Vec3d r = reference_point(mesh);
  // Over the tetrahedra (r, a, b, c), with a, b, c relative to r and det = a . (b x c):
  //   volume          det / 6
  //   first moment    det / 24 (a + b + c)
  //   second moment   det / 120 (a_i a_j + b_i b_j + c_i c_j + s_i s_j),  s = a + b + c.
  double six_volume = 0;
  Vec3d first;
  double second[3][3] = {};
  for (Face f : mesh.faces()) {
    const Halfedge h = mesh.halfedge(f);
    const Vec3d a = to_double(mesh.position(mesh.to_vertex(h))) - r;
    const Vec3d b = to_double(mesh.position(mesh.to_vertex(mesh.next(h)))) - r;
    const Vec3d c = to_double(mesh.position(mesh.from_vertex(h))) - r;
    const double det = dot(a, cross(b, c));
    const Vec3d s = a + b + c;
    six_volume += det;
    first += s * det;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = i; j < 3; ++j)
        second[i][j] += det * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j]);
  }
  const double volume = six_volume / 6;
  if (!(volume > 0))
    throw InvalidInputError("mass_properties: the mesh encloses a volume of " + number(volume) +
                            ", not a positive one (empty, or faces wound inward?)");
  MassProperties m;
  m.volume = volume;
  m.mass = density * volume;
  const Vec3d com = first * (1.0 / (24 * volume));  // relative to r
  m.centre_of_mass = r + com;
  // The second moments about the centre of mass (parallel axis).
  double cov[3][3];
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = i; j < 3; ++j)
      cov[i][j] = cov[j][i] = density * (second[i][j] / 120 - volume * com[i] * com[j]);
  set_inertia(m, cov);
  return m;
}

MassProperties shell_mass_properties(const SurfaceMesh& mesh, double density, double thickness) {
  check_positive(density, "density", "shell_mass_properties");
  check_positive(thickness, "thickness", "shell_mass_properties");
  check_triangles(mesh, "shell_mass_properties");
  const Vec3d r = reference_point(mesh);
  // Over the triangles (a, b, c), relative to r, of area A and unit normal n, s = a + b + c:
  //   area            A
  //   first moment    A / 3 s
  //   second moment   A / 12 (a_i a_j + b_i b_j + c_i c_j + s_i s_j), plus the slab's
  //                   thickness^2 A / 12 n_i n_j across the triangle.
  double area = 0;
  Vec3d first;
  double second[3][3] = {};
  const double across = thickness * thickness;
  for (Face f : mesh.faces()) {
    const Halfedge h = mesh.halfedge(f);
    const Vec3d a = to_double(mesh.position(mesh.to_vertex(h))) - r;
    const Vec3d b = to_double(mesh.position(mesh.to_vertex(mesh.next(h)))) - r;
    const Vec3d c = to_double(mesh.position(mesh.from_vertex(h))) - r;
    const Vec3d twice = cross(b - a, c - a);
    const double twice_area = norm(twice);
    if (!(twice_area > 0)) continue;
    const double A = twice_area / 2;
    const Vec3d n = twice * (1.0 / twice_area);
    const Vec3d s = a + b + c;
    area += A;
    first += s * (A / 3);
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = i; j < 3; ++j)
        second[i][j] +=
            A / 12 * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j] + across * n[i] * n[j]);
  }
  if (!(area > 0))
    throw InvalidInputError("shell_mass_properties: the surface has an area of " + number(area) +
                            ", not a positive one");
  MassProperties m;
  m.volume = area * thickness;
  m.mass = density * m.volume;
  const Vec3d com = first * (1.0 / area);  // relative to r
  m.centre_of_mass = r + com;
  const double sigma = density * thickness;  // mass per unit area
  double cov[3][3];
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = i; j < 3; ++j)
      cov[i][j] = cov[j][i] = sigma * (second[i][j] - area * com[i] * com[j]);
  set_inertia(m, cov);
  return m;
}

}  // namespace hedge
