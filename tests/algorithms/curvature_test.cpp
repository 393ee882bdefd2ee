#include "hedge/algorithms/curvature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/core/build.h"
#include "non_finite.h"
#include "test_meshes.h"

namespace hedge {
namespace {

// An icosahedron refined `steps` times at the edge midpoints and pushed onto the sphere of radius r
// about the origin: close to uniform triangles, outward normals.
SurfaceMesh sphere(float r, int steps, bool inside_out = false) {
  const float t = (1 + std::sqrt(5.f)) / 2;
  IndexedMesh in;
  in.positions = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                  {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  in.indices = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
  if (inside_out)
    for (std::size_t i = 0; i < in.indices.size(); i += 3) std::swap(in.indices[i + 1], in.indices[i + 2]);
  SurfaceMesh m = build(in);
  subdivide(m, Subdivision::midpoint, steps);
  for (Vertex v : m.vertices()) {
    const Vec3 p = m.position(v);
    m.position(v) = p * (r / norm(p));
  }
  return m;
}

// The cotangent formulas are accurate where the mesh is regular (valence 6) and off by up to a
// sixth at the twelve vertices of valence 5 that the icosahedron leaves; over the whole sphere the
// area-weighted mean is close to the exact value.
double tolerance(const SurfaceMesh& m, Vertex v, double regular) { return m.valence(v) == 6 ? regular : 0.2; }

double area_weighted_mean(const SurfaceMesh& m, const std::vector<double>& x) {
  const std::vector<double> area = vertex_areas(m);
  double sum = 0, total = 0;
  for (Vertex v : m.vertices()) {
    sum += x[v.idx()] * area[v.idx()];
    total += area[v.idx()];
  }
  return sum / total;
}

TEST(Curvature, ASpheresMeanCurvatureIsOneOverItsRadius) {
  for (float r : {0.5f, 2.f, 10.f}) {
    const SurfaceMesh m = sphere(r, 4);
    const std::vector<double> h = mean_curvature(m);
    ASSERT_EQ(h.size(), m.vertex_slots());
    for (Vertex v : m.vertices())
      EXPECT_NEAR(h[v.idx()] * r, 1, tolerance(m, v, 0.02)) << "r " << r << ", vertex " << v.idx();
    EXPECT_NEAR(area_weighted_mean(m, h) * r, 1, 0.01) << "r " << r;
    EXPECT_EQ(m.validate(), std::vector<std::string>{});
  }
}

TEST(Curvature, MeanCurvatureIsNegativeForInwardNormals) {
  const SurfaceMesh m = sphere(2, 3, true);
  const std::vector<double> h = mean_curvature(m);
  for (Vertex v : m.vertices()) EXPECT_NEAR(h[v.idx()] * -2, 1, tolerance(m, v, 0.02)) << v.idx();
  EXPECT_NEAR(area_weighted_mean(m, h) * -2, 1, 0.01);
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
}

// Gauss-Bonnet: the angle defects (curvature times vertex area) of a closed surface sum to 2 pi
// times its Euler characteristic, 4 pi for a sphere, whatever the mesh.
double total_defect(const SurfaceMesh& m, const std::vector<double>& k) {
  const std::vector<double> area = vertex_areas(m);
  double total = 0;
  for (Vertex v : m.vertices()) total += k[v.idx()] * area[v.idx()];
  return total;
}

TEST(Curvature, ASpheresGaussianCurvatureIsOneOverItsRadiusSquared) {
  const float r = 3;
  const SurfaceMesh m = sphere(r, 4);
  const std::vector<double> k = gaussian_curvature(m);
  for (Vertex v : m.vertices()) EXPECT_NEAR(k[v.idx()] * r * r, 1, tolerance(m, v, 0.03)) << v.idx();
  EXPECT_NEAR(area_weighted_mean(m, k) * r * r, 1, 0.01);
  EXPECT_NEAR(total_defect(m, k), 4 * std::numbers::pi, 1e-9);
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
}

TEST(Curvature, APlaneHasNoneAndItsBoundaryIsLeftAtZero) {
  SurfaceMesh m = build(test::triangle_lattice(6));
  for (Vertex v : m.vertices()) m.position(v).z = 0.25f * m.position(v).x - 0.5f * m.position(v).y + 3;
  const std::vector<double> h = mean_curvature(m), k = gaussian_curvature(m);
  for (Vertex v : m.vertices()) {
    EXPECT_NEAR(h[v.idx()], 0, 1e-5) << v.idx();
    EXPECT_NEAR(k[v.idx()], 0, 1e-5) << v.idx();
  }
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
}

TEST(Curvature, PolygonsCountAsTheirFanTriangles) {
  // A cube of quads: every corner meets three right angles, a defect of pi / 2, and the vertex
  // areas come from the fan triangles of the quads; the defects still sum to 4 pi.
  const SurfaceMesh m = build(test::cube());
  const std::vector<double> k = gaussian_curvature(m), h = mean_curvature(m);
  for (Vertex v : m.vertices()) {
    EXPECT_GT(k[v.idx()], 0) << v.idx();
    EXPECT_GT(h[v.idx()], 0) << v.idx();  // convex, outward normals
  }
  EXPECT_NEAR(total_defect(m, k), 4 * std::numbers::pi, 1e-9);
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
}

TEST(Curvature, TheEmptyMeshHasNoValues) {
  const SurfaceMesh m;
  EXPECT_TRUE(mean_curvature(m).empty());
  EXPECT_TRUE(gaussian_curvature(m).empty());
}

TEST(Curvature, RefusesANonFinitePosition) {
  SurfaceMesh m = build(test::grid(4, true));
  test::expect_refuses_non_finite(m, Vertex(6), "mean_curvature", [&] { mean_curvature(m); });
  test::expect_refuses_non_finite(m, Vertex(6), "gaussian_curvature", [&] { gaussian_curvature(m); });
}

}  // namespace
}  // namespace hedge
