// A seeded random sweep of solid fracture over the closed meshes of data/ (and of ../shared/meshes
// when present): every piece and the remaining object closed and valid, the volume conserved.
// A strike that cannot be made closed is refused with the mesh unchanged; the sweep allows 0.5% of
// them (see docs/fracture.md). `./test` runs a few hundred impacts; HEDGE_SWEEP=N runs N (the
// opt-in sweep of 10^4):
//   HEDGE_SWEEP=10000 build/release/tests/hedge_tests --gtest_filter='FractureSolidSweep.*'
// Every failed or refused strike is printed with its number, mesh, face, impact, preset, radius
// fraction and seed. HEDGE_SWEEP_AT=i replays strike i alone (with the same HEDGE_SWEEP set or
// not, so the list of meshes is the same); HEDGE_SWEEP_MESH=name keeps the meshes whose file
// name contains `name` (the strikes are then numbered over those only).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "fracture_solid_checks.h"
#include "hedge/algorithms/fracture_solid.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/core/triangulate.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "test_meshes.h"

namespace hedge {
namespace {

// The test's own generator for its choices (impacts, presets), independent of the library's.
struct TestRng {
  std::uint64_t s;
  std::uint64_t next() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return s >> 11;
  }
  double uniform() { return double(next() >> 11) * 0x1.0p-42; }
};

std::vector<std::string> closed_meshes() {
  std::vector<std::string> paths;
  for (const char* name : {"tet.obj", "icosahedron_binary.stl", "bob_small.ply", "anchor.off",
                           "spot_control_mesh.obj", "fandisk_quads.off", "spot_triangulated.obj"})
    paths.push_back(test::data_path(name));
  if (std::getenv("HEDGE_SWEEP")) {
    // The closed meshes of ../shared/meshes (its README), when the folder is there.
    for (const char* name : {"fandisk.off", "turbine.off", "bunny.off", "cube1Binary.stl",
                             "spot_quadrangulated.obj", "double-torus-example.off", "quadknot.obj"})
      if (std::filesystem::exists(test::shared_mesh_path(name)))
        paths.push_back(test::shared_mesh_path(name));
  }
  if (const char* only = std::getenv("HEDGE_SWEEP_MESH")) {
    std::vector<std::string> kept;
    for (const std::string& p : paths)
      if (std::filesystem::path(p).filename().string().find(only) != std::string::npos) kept.push_back(p);
    paths.swap(kept);
  }
  return paths;
}

TEST(FractureSolidSweep, RandomImpactsLeaveClosedPiecesAndConserveVolume) {
  const char* env = std::getenv("HEDGE_SWEEP");
  const char* at_env = std::getenv("HEDGE_SWEEP_AT");
  const int at = at_env ? std::atoi(at_env) : -1;
  const int impacts = at >= 0 ? at + 1 : env ? std::atoi(env) : 210;
  const std::vector<std::string> paths = closed_meshes();
  ASSERT_FALSE(paths.empty()) << "no mesh left by HEDGE_SWEEP_MESH";
  std::vector<SurfaceMesh> meshes;
  for (const std::string& p : paths) meshes.push_back(read_mesh(p));
  const std::vector<std::string> presets = fracture_material_names();
  TestRng rng{12345};
  int struck = 0, pieces = 0, refused = 0, bad = 0;
  double worst = 0;  // the largest relative error of the volume
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < impacts; ++i) {
    const std::size_t which = i % meshes.size();
    // Every strike draws the same numbers, so strike i can be replayed alone.
    const std::uint64_t face_draw = rng.next(), corner_draw = rng.next();
    const double u0 = rng.uniform(), w0 = rng.uniform();
    const std::uint64_t preset_draw = rng.next();
    const double fraction = rng.uniform();
    const std::uint64_t seed = rng.next();
    if (i < at) continue;
    ++struck;
    SurfaceMesh m = meshes[which];
    const double before = volume(m);
    const Face f(static_cast<Index>(face_draw % m.n_faces()));
    // A point of one of the face's fan triangles (fan_start(): the triangles the surface is made
    // of), by random barycentric weights.
    std::vector<Vec3d> c;
    const Halfedge start = fan_start(m, f);
    Halfedge h = start;
    do {
      c.push_back(to_double(m.position(m.to_vertex(h))));
      h = m.next(h);
    } while (h != start);
    const std::size_t k = 1 + corner_draw % (c.size() - 2);
    double u = u0, w = w0;
    if (u + w > 1) u = 1 - u, w = 1 - w;
    const Vec3 impact = to_float(c[0] + (c[k] - c[0]) * u + (c[k + 1] - c[0]) * w);
    SolidFractureOptions o;
    o.material = fracture_material(presets[preset_draw % presets.size()]);
    o.radius_fraction = 0.05 + 0.55 * fraction;
    o.seed = seed;
    o.hulls = i % 8 == 0;
    char text[400];
    std::snprintf(text, sizeof text,
                  " strike %d at face %d, impact {%.9gf, %.9gf, %.9gf}, material \"%s\", radius_fraction "
                  "%.17g, seed %llu, hulls %d",
                  i, static_cast<int>(f.idx()), double(impact.x), double(impact.y), double(impact.z),
                  o.material.name.c_str(), o.radius_fraction, static_cast<unsigned long long>(o.seed),
                  int(o.hulls));
    const std::string what = std::filesystem::path(paths[which]).filename().string() + text;
    try {
      const SolidFractureResult r = fracture_solid(m, impact, o);
      pieces += static_cast<int>(r.pieces.size());
      const int parts = ::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count();
      solid_test::expect_solid_strike(m, r, before);
      double total = m.n_faces() ? volume(m) : 0.0;
      for (const SolidPiece& p : r.pieces) total += volume(p.mesh);
      worst = std::max(worst, std::abs(total - before) / std::abs(before));
      if (::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count() != parts) {
        ADD_FAILURE() << what;
        if (++bad >= 10) return;
      }
    } catch (const InvalidInputError& e) {
      // A strike that could not be made closed is refused with the mesh unchanged (checked).
      ++refused;
      EXPECT_EQ(volume(m), before) << what;
      EXPECT_EQ(solid_test::solid_problem(m), "") << what;
      std::printf("refused: %s: %s\n", what.c_str(), e.what());
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // None of 10^4 strikes is refused (docs/fracture.md); a refusal is safe, so a few are allowed.
  EXPECT_LE(refused, struck / 200 + 1);
  std::printf(
      "sweep: %d impacts over %zu meshes, %d pieces, %d refused, %d failed, largest volume error %.2g "
      "relative, %.1f s\n",
      struck, meshes.size(), pieces, refused, bad, worst, seconds);
}

}  // namespace
}  // namespace hedge
