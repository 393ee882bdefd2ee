#include "hedge/algorithms/smooth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <vector>

#include "hedge/algorithms/geometry.h"
#include "hedge/core/build.h"
#include "hedge/core/changes.h"
#include "hedge/core/export.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "non_finite.h"
#include "test_meshes.h"

namespace hedge {
namespace {

// An n x n grid of triangles in z = 0, its interior vertices jittered in x and y (irregular but
// flat) and, with noise > 0, in z.
SurfaceMesh bumpy_grid(int n, float jitter, float noise, unsigned seed) {
  IndexedMesh in = test::grid(n, true);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1, 1);
  for (Vec3& p : in.positions) {
    const bool interior = p.x > 0 && p.y > 0 && p.x < n && p.y < n;
    if (!interior) continue;
    p.x += jitter * u(rng);
    p.y += jitter * u(rng);
    p.z += noise * u(rng);
  }
  return build(in);
}

double z_spread(const SurfaceMesh& m) {
  double s = 0;
  for (Vertex v : m.vertices()) s += double(m.position(v).z) * m.position(v).z;
  return std::sqrt(s / double(m.n_vertices()));
}

TEST(Smooth, UniformRemovesNoiseAndKeepsTheBoundary) {
  SurfaceMesh m = bumpy_grid(10, 0, 0.3f, 1);
  const SurfaceMesh before = m;
  const double spread = z_spread(m);
  smooth(m, {.method = SmoothMethod::uniform, .iterations = 20});
  EXPECT_LT(z_spread(m), 0.2 * spread);
  for (Vertex v : m.vertices())
    if (m.is_boundary(v)) EXPECT_EQ(m.position(v), before.position(v));
  EXPECT_TRUE(m.validate().empty());
}

// A flat patch of a triangular lattice (all angles near 60 degrees), its interior vertices jittered
// in the plane: irregular, but with no obtuse angle.
SurfaceMesh jittered_lattice(int n, float jitter, unsigned seed) {
  IndexedMesh in = test::triangle_lattice(n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1, 1);
  for (int j = 1; j < n; ++j)
    for (int i = 1; i < n; ++i)
      in.positions[std::size_t(j * (n + 1) + i)] += Vec3{jitter * u(rng), jitter * u(rng), 0};
  return build(in);
}

TEST(Smooth, CotangentLeavesAFlatIrregularMeshInPlace) {
  // On a plane the cotangent Laplacian of the positions is zero: nothing moves (up to rounding),
  // while the uniform one pulls the jittered vertices toward their neighbours' centroid.
  SurfaceMesh cot = jittered_lattice(8, 0.12f, 2);
  SurfaceMesh uni = cot;
  const SurfaceMesh before = cot;
  smooth(cot, {.method = SmoothMethod::cotangent, .iterations = 5});
  smooth(uni, {.method = SmoothMethod::uniform, .iterations = 5});
  double cot_move = 0, uni_move = 0;
  for (Vertex v : before.vertices()) {
    cot_move = std::max(cot_move, double(norm(cot.position(v) - before.position(v))));
    uni_move = std::max(uni_move, double(norm(uni.position(v) - before.position(v))));
    EXPECT_EQ(cot.position(v).z, 0);
  }
  EXPECT_LT(cot_move, 1e-5);
  EXPECT_GT(uni_move, 0.03);
  EXPECT_TRUE(cot.validate().empty());
}

// An n x n grid of right triangles in z = 0, its interior vertices moved by up to `jitter` in x and
// y by the library's seeded generator: flat, with obtuse angles (negative cotangent weights).
SurfaceMesh jittered_grid(int n, double jitter, std::uint64_t seed) {
  IndexedMesh in = test::grid(n, true);
  SplitMix64 rng(seed);
  for (Vec3& p : in.positions) {
    const double dx = jitter * (2 * rng.uniform() - 1), dy = jitter * (2 * rng.uniform() - 1);
    if (p.x > 0 && p.y > 0 && p.x < float(n) && p.y < float(n)) p += Vec3{float(dx), float(dy), 0};
  }
  return build(in);
}

double largest_move(const SurfaceMesh& before, const SurfaceMesh& after) {
  double most = 0;
  for (Vertex v : before.vertices())
    most = std::max(most, norm(to_double(after.position(v)) - to_double(before.position(v))));
  return most;
}

TEST(Smooth, ObtuseAnglesDoNotMoveAFlatGrid) {
  // The cotangent Laplacian of a plane is zero with every weight kept, negative ones included:
  // explicit and implicit steps leave the jittered grid where it is.
  const SurfaceMesh grid = jittered_grid(10, 0.3, 11);
  int obtuse = 0;
  for (double w : cotangent_weights(grid)) obtuse += w < 0;
  ASSERT_GT(obtuse, 5);
  for (SmoothMethod method : {SmoothMethod::cotangent, SmoothMethod::implicit})
    for (int iterations : {1, 10}) {
      SCOPED_TRACE(::testing::Message() << (method == SmoothMethod::implicit ? "implicit" : "cotangent")
                                        << ", " << iterations << " iterations");
      SurfaceMesh m = grid;
      smooth(m, {.method = method, .iterations = iterations});
      EXPECT_LT(largest_move(grid, m), 1e-6);
      for (Vertex v : m.vertices()) EXPECT_EQ(m.position(v).z, 0);
      EXPECT_TRUE(m.validate().empty());
    }
}

// Faces whose normal after makes more than 90 degrees with their normal before, and faces of
// positive area before and of zero area after.
struct Damage {
  int turned = 0, collapsed = 0;
};
Damage damage(const SurfaceMesh& before, const SurfaceMesh& after) {
  Damage d;
  for (Face f : before.faces()) {
    const Vec3d a = area_vector(before, f), b = area_vector(after, f);
    if (dot(a, a) == 0) continue;
    d.collapsed += dot(b, b) == 0;
    d.turned += dot(b, b) > 0 && dot(a, b) < 0;
  }
  return d;
}

TEST(Smooth, NoFaceTurnsOverOnTheDataMeshes) {
  // Ten iterations with the defaults on every mesh in data/ (triangulated where needed): the
  // cotangent methods turn no face over and collapse none.
  int meshes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::data_path(""))) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl") continue;
    SurfaceMesh input = read_mesh(entry.path().string());
    bool polygons = false;
    for (Face f : input.faces()) polygons = polygons || input.valence(f) != 3;
    if (polygons) input = build(to_indexed(input, {.triangulation = Triangulation::ear}));
    for (SmoothMethod method : {SmoothMethod::cotangent, SmoothMethod::implicit}) {
      SCOPED_TRACE(entry.path().filename().string() +
                   (method == SmoothMethod::implicit ? ", implicit" : ", cotangent"));
      SurfaceMesh m = input;
      smooth(m, {.method = method});
      const Damage d = damage(input, m);
      EXPECT_EQ(d.turned, 0);
      EXPECT_EQ(d.collapsed, 0);
      EXPECT_TRUE(m.validate().empty());
    }
    ++meshes;
  }
  EXPECT_GE(meshes, 15);
}

// A square plate of side 20 with a pin of radius `radius` and height 20 standing on it, 8 sides and
// 6 rings of 16 faces along its length, closed by a fan at its tip: most edges are long, the pin's
// rings are tiny. The plate's four corners are its boundary.
SurfaceMesh plate_with_pin(float radius) {
  IndexedMesh in;
  const Vec3 centre{3, 3, 0};
  constexpr int kSides = 8, kRings = 7;
  for (int c = 0; c < 4; ++c) {  // corners at 45, 135, 225 and 315 degrees
    const double a = std::numbers::pi / 4 + c * std::numbers::pi / 2;
    in.positions.push_back(centre + Vec3{float(14 * std::cos(a)), float(14 * std::sin(a)), 0});
  }
  for (int r = 0; r < kRings; ++r)
    for (int i = 0; i < kSides; ++i) {
      const double a = i * std::numbers::pi / 4;
      in.positions.push_back(
          centre + Vec3{float(radius * std::cos(a)), float(radius * std::sin(a)), float(r * 20.0 / kRings)});
    }
  in.positions.push_back(centre + Vec3{0, 0, 20});
  auto ring = [&](int r, int i) { return Index(4 + r * kSides + (i % kSides)); };
  auto tri = [&](Index a, Index b, Index c) { in.indices.insert(in.indices.end(), {a, b, c}); };
  // The plate: each corner takes the two ring edges facing it, and each side of the square a
  // triangle to the ring vertex between its corners.
  for (int i = 0; i < kSides; ++i) tri(ring(0, i + 1), ring(0, i), Index(i / 2));
  for (int c = 0; c < 4; ++c) tri(Index(c), Index((c + 1) % 4), ring(0, 2 + 2 * c));
  for (int r = 0; r + 1 < kRings; ++r)
    for (int i = 0; i < kSides; ++i) {
      tri(ring(r, i), ring(r, i + 1), ring(r + 1, i + 1));
      tri(ring(r, i), ring(r + 1, i + 1), ring(r + 1, i));
    }
  for (int i = 0; i < kSides; ++i)
    tri(ring(kRings - 1, i), ring(kRings - 1, i + 1), Index(4 + kRings * kSides));
  return build(in);
}

TEST(Smooth, ImplicitStepsFollowTheLocalSize) {
  // A pin 300 times thinner than the mean edge: a time step in units of the mean edge would
  // squash it to a segment in one step; steps relative to each vertex's size thin it gradually.
  const SurfaceMesh start = plate_with_pin(0.01f);
  ASSERT_TRUE(start.validate().empty());
  ASSERT_TRUE(start.is_boundary(Vertex(0)));
  SurfaceMesh m = start;
  smooth(m, {.method = SmoothMethod::implicit});
  const Damage d = damage(start, m);
  EXPECT_EQ(d.collapsed, 0);
  EXPECT_EQ(d.turned, 0);
  // The ring halfway up keeps a fair part of its radius.
  const Vertex a(4 + 3 * 8), b(4 + 3 * 8 + 4);  // opposite corners of ring 3
  const double radius = 0.5 * norm(to_double(m.position(a)) - to_double(m.position(b)));
  EXPECT_GT(radius, 0.001) << "of 0.01";
  EXPECT_LT(radius, 0.008) << "of 0.01";
  EXPECT_TRUE(m.validate().empty());
}

TEST(Smooth, TaubinShrinksFarLessThanUniform) {
  const SurfaceMesh start = read_mesh(test::data_path("spot_triangulated.obj"));
  const double v0 = volume(start);
  SurfaceMesh uni = start, taubin = start, cot = start;
  smooth(uni, {.method = SmoothMethod::uniform, .iterations = 10});
  smooth(taubin, {.method = SmoothMethod::taubin, .iterations = 10});
  smooth(cot, {.method = SmoothMethod::cotangent, .iterations = 10});
  const double lost_uniform = 1 - volume(uni) / v0, lost_taubin = std::abs(1 - volume(taubin) / v0);
  EXPECT_GT(lost_uniform, 0.05);
  EXPECT_LT(lost_taubin, 0.25 * lost_uniform);
  EXPECT_GT(1 - volume(cot) / v0, 0);  // the cotangent flow shrinks too
  EXPECT_TRUE(uni.validate().empty());
  EXPECT_TRUE(taubin.validate().empty());
  EXPECT_TRUE(cot.validate().empty());
}

TEST(Smooth, AFreeBoundaryMovesAlongItself) {
  SurfaceMesh m = bumpy_grid(6, 0, 0.2f, 3);
  // One iteration: every side vertex has two collinear boundary neighbours and stays on its side;
  // only the four corners are pulled inside.
  smooth(m, {.method = SmoothMethod::uniform, .iterations = 1, .fix_boundary = false});
  int moved_corners = 0;
  for (Vertex v : m.vertices()) {
    if (!m.is_boundary(v)) continue;
    const Vec3 p = m.position(v);
    // Sides stay on their lines; corners are pulled inside.
    const bool on_side = p.x == 0 || p.y == 0 || p.x == 6 || p.y == 6;
    const bool corner_moved = !on_side;
    moved_corners += corner_moved;
    EXPECT_EQ(p.z, 0);
  }
  EXPECT_EQ(moved_corners, 4);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Smooth, TheMaskChoosesWhoMoves) {
  SurfaceMesh m = bumpy_grid(6, 0, 0.3f, 4);
  const SurfaceMesh before = m;
  std::vector<std::uint8_t> mask(m.vertex_slots(), 0);
  mask[24] = 1;  // (3, 3), an interior vertex
  smooth(m, {.iterations = 5, .mask = mask});
  for (Vertex v : m.vertices()) {
    if (v.idx() == 24)
      EXPECT_NE(m.position(v), before.position(v));
    else
      EXPECT_EQ(m.position(v), before.position(v));
  }
  EXPECT_TRUE(m.validate().empty());
}

TEST(Smooth, MovesAreMarkedOnce) {
  SurfaceMesh m = bumpy_grid(4, 0, 0.3f, 5);
  const ChangeConsumer watch(m.watch_changes());
  int notified = 0;
  m.changes().subscribe(ChangeEvent::vertices_moved, [&](ChangeEvent) { ++notified; });
  smooth(m, {.iterations = 7});
  EXPECT_EQ(notified, 1);
  EXPECT_EQ(watch.pending().vertices.size(), 9u);  // the 3 x 3 interior vertices
  EXPECT_TRUE(m.validate().empty());
}

TEST(Smooth, ImplicitTakesOneLargeStableStep) {
  // One backward Euler step with a large time step flattens the noise; explicit steps of that
  // size do not exist (lambda is at most 1), and the flat irregular lattice stays in place.
  SurfaceMesh m = bumpy_grid(10, 0, 0.3f, 8);
  const SurfaceMesh before = m;
  const double spread = z_spread(m);
  smooth(m, {.method = SmoothMethod::implicit, .iterations = 1, .lambda = 20});
  EXPECT_LT(z_spread(m), 0.25 * spread);
  for (Vertex v : m.vertices()) {
    EXPECT_TRUE(std::isfinite(m.position(v).z));
    if (m.is_boundary(v)) EXPECT_EQ(m.position(v), before.position(v));
  }
  SurfaceMesh flat = jittered_lattice(8, 0.12f, 9);
  const SurfaceMesh flat_before = flat;
  smooth(flat, {.method = SmoothMethod::implicit, .iterations = 3, .lambda = 5});
  for (Vertex v : flat.vertices()) EXPECT_LT(norm(flat.position(v) - flat_before.position(v)), 1e-4);
  // On a closed surface it shrinks, as the cotangent flow does, but stays valid and finite.
  SurfaceMesh spot = read_mesh(test::data_path("spot_triangulated.obj"));
  const double v0 = volume(spot);
  smooth(spot, {.method = SmoothMethod::implicit, .iterations = 2, .lambda = 1});
  EXPECT_LT(volume(spot), v0);
  EXPECT_GT(volume(spot), 0.5 * v0);
  EXPECT_TRUE(m.validate().empty());
  EXPECT_TRUE(flat.validate().empty());
  EXPECT_TRUE(spot.validate().empty());
}

TEST(Smooth, ProgressRisesToOneAndAThrowingCallbackChangesNothing) {
  for (SmoothMethod method : {SmoothMethod::uniform, SmoothMethod::implicit}) {
    SurfaceMesh m = bumpy_grid(6, 0, 0.3f, 4);
    std::vector<double> seen;
    smooth(m, {.method = method, .iterations = 4, .lambda = 0.5, .progress = [&](double f) {
                 seen.push_back(f);
               }});
    ASSERT_FALSE(seen.empty());
    for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_GT(seen[i], seen[i - 1]);
    EXPECT_DOUBLE_EQ(seen.back(), 1.0);
    EXPECT_GT(seen.front(), 0.0);

    const SurfaceMesh before = m;
    struct Stop {};
    auto stop = [](double f) {
      if (f > 0.4) throw Stop{};
    };
    EXPECT_THROW(smooth(m, {.method = method, .iterations = 4, .lambda = 0.5, .progress = stop}), Stop);
    for (Vertex v : m.vertices()) EXPECT_EQ(m.position(v), before.position(v));
    EXPECT_TRUE(m.validate().empty());
  }
}

TEST(Smooth, BadOptionsChangeNothing) {
  SurfaceMesh m = bumpy_grid(4, 0, 0.3f, 6);
  const SurfaceMesh before = m;
  EXPECT_THROW(smooth(m, {.iterations = -1}), InvalidInputError);
  EXPECT_THROW(smooth(m, {.lambda = 0}), InvalidInputError);
  EXPECT_THROW(smooth(m, {.lambda = std::nan("")}), InvalidInputError);
  EXPECT_THROW(smooth(m, {.method = SmoothMethod::taubin, .mu = -0.2}), InvalidInputError);
  EXPECT_THROW(smooth(m, {.method = SmoothMethod::implicit, .lambda = -1}), InvalidInputError);
  EXPECT_THROW(smooth(m, {.method = SmoothMethod::implicit, .lambda = std::nan("")}), InvalidInputError);
  std::vector<std::uint8_t> short_mask(3, 1);
  EXPECT_THROW(smooth(m, {.mask = short_mask}), InvalidInputError);
  SurfaceMesh quads = build(test::grid(3, false));
  try {
    smooth(quads, {.method = SmoothMethod::cotangent});
    FAIL() << "cotangent weights on quads";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("face 0 has 4 corners"), std::string::npos) << e.what();
  }
  for (Vertex v : m.vertices()) EXPECT_EQ(m.position(v), before.position(v));
  smooth(quads, {.method = SmoothMethod::taubin, .iterations = 2});  // polygons are fine otherwise
  EXPECT_TRUE(quads.validate().empty());
  EXPECT_TRUE(m.validate().empty());
}

TEST(Smooth, RefusesANonFinitePositionBeforeMovingAnything) {
  SurfaceMesh m = build(test::grid(5, true));
  test::expect_refuses_non_finite(m, Vertex(7), "smooth", [&] { smooth(m); });
  test::expect_refuses_non_finite(m, Vertex(7), "smooth",
                                  [&] { smooth(m, {.method = SmoothMethod::implicit}); });
}

}  // namespace
}  // namespace hedge
