// Google Benchmark binary for hedge's own operations: one BM_<op>/<mesh> per operation of the hedge
// backend (peer_hedge.cpp) and per mesh, so operations added there show up here too.
//
//   hedge_bench [benchmark flags, e.g. --benchmark_min_time=0.05] [--root DIR] [mesh[:subN] ...]
//
// Without meshes it uses the same default list as `peers` (../shared/meshes, else data/).
//
// BM_one_ring_order/<mesh>/{as_loaded,shuffled,spatial,vertex_cache}: one-ring circulation over
// every vertex of the mesh as loaded, after a random renumbering of its vertices, edges and faces,
// and after reorder() of the shuffled mesh in either ordering: the cost of a lost element order, and
// what reordering gets back (algorithms/reorder.h). The counter "acmr" is each order's average cache
// miss ratio (vertex loads per triangle through a 16-entry FIFO cache), which the vertex_cache
// ordering lowers for a GPU drawing the faces in index order.
//
// BM_convex_hull/<n>: the convex hull of n random points in a ball (200: a shard's size).
// BM_convex_hull_pieces/<points>: the hulls of the pieces of one solid strike on sphere_100k (as
// BM_fracture_solid's first strike, 64 or 200 break points), each of its vertex set, all pieces per
// iteration (the time is for all of them); counters: the pieces and their mean vertex count. A
// piece's points are nearly all on its hull (a convex mesh cut by convex cells), unlike a ball's.
// BM_triangulate_polygon/<shape>/<n>: ear clipping (core/triangulate.h) of one polygon of n corners:
// a circle with each corner moved in or out at random (jitter, about half of the corners
// reflex), a comb (every other corner reflex), and a zigzag strip numbered from the middle of one
// side (ears only at its two ends, far from corner 0: the case a scan from corner 0 after every
// clip made cubic).
// BM_decimate/<mesh>: quadric decimation to 10% of the vertices (algorithms/decimate.h), the copy of
// the mesh excluded from the time; the counters give the vertices reached and the largest error.
// BM_fracture/<mesh>: one impact, glass preset (algorithms/fracture.h) with its break radius in edge
// lengths of the impact face (7, units edge_lengths), so the broken area holds about the same faces
// on every mesh, on a flat plate of 100k and of 1M triangles (plate_100k, plate_1m) and on igea.ply
// from ../shared/meshes when it is there. BM_fracture_diagonal/<mesh>: the same with the preset's
// own radius, 0.13 of the mesh's diagonal: the broken area is the same share of every mesh, so its
// faces, and the time, grow with the resolution.
// Impacts hit the centroid of a random live face of the same mesh, its FaceBvh kept up to date by
// fracture(), as in a game; when a fifth of the faces has broken off, the mesh and its tree are
// restored with the timer paused. Counters: shards and faces per impact, and the mean
// microseconds of each stage (locate, scatter, cut, detach, hulls).
// BM_capi_fracture/<mesh>: the same impacts through the C ABI (hedge_mesh_fracture), as an engine
// binding makes them: a mesh handle made of the same triangles, the same generator for the faces
// hit and the seeds, the handle's picking tree built with the timer paused (hedge_mesh_bvh_update)
// and kept up to date by the strikes; restored as BM_fracture restores. Shards are made into
// handles by the call and destroyed with the timer paused. Counters as BM_fracture's, without the
// stages.
// BM_fracture_solid/<mesh>/<points>: one solid strike (algorithms/fracture_solid.h) on a closed
// sphere of 100k (sphere_100k) or 1M (sphere_1m) triangles of radius 1, or of 1M triangles of
// radius sqrt(10) (sphere_1m_r3: the triangles of sphere_100k's size, so the broken region holds
// as many of them), break radius 0.5 (model units, the same on all), with a material of 64 or 200
// break points in two shells (about 40 or 110 pieces: not every cell holds part of the sphere),
// and on sphere_100k 52 and 182 points, about the 32 and 100 pieces of the bars. Impacts at the
// surface point nearest to a random direction, the FaceBvh kept up to date by the strikes; the mesh and its
// tree are restored (timer paused) every 4 strikes. The CPU time is the process's: the cells'
// worker threads (core/threads.h) included. Counters: pieces per strike, median and p99
// microseconds, and the mean microseconds of each stage (locate, cells, clip, cap, assemble,
// per_piece).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "bench_common.h"
#include "grid_sphere.h"
#include "hedge/algorithms/convex_hull.h"
#include "hedge/algorithms/decimate.h"
#include "hedge/algorithms/fracture.h"
#include "hedge/algorithms/fracture_solid.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/locate.h"
#include "hedge/algorithms/reorder.h"
#include "hedge/c_api.h"
#include "hedge/core/build.h"
#include "hedge/core/operations.h"
#include "hedge/core/triangulate.h"
#include "indexed_subdivide.h"

namespace {

struct Loaded {
  bench::Input input;
  bench::Scratch scratch;
  std::unique_ptr<bench::MeshBox> reference;
};

void run_op(benchmark::State& state, const bench::OpImpl* impl, Loaded* l) {
  for (auto _ : state) {
    std::unique_ptr<bench::MeshBox> work;
    if (impl->prepare) {
      state.PauseTiming();
      work = impl->prepare(*l->reference);
      state.ResumeTiming();
    }
    bench::Context ctx{l->input, work ? work.get() : l->reference.get(), l->scratch, nullptr};
    benchmark::DoNotOptimize(impl->run(ctx));
    state.PauseTiming();
    ctx.out.reset();
    work.reset();
    state.ResumeTiming();
  }
  state.counters["vertices"] = static_cast<double>(l->input.n_vertices());
}

// A random renumbering of every element.
void shuffle(hedge::SurfaceMesh& m, unsigned seed) {
  std::mt19937 rng(seed);
  auto perm = [&](std::size_t n) {
    std::vector<hedge::Index> p(n);
    std::iota(p.begin(), p.end(), 0);
    std::shuffle(p.begin(), p.end(), rng);
    return p;
  };
  m.renumber(perm(m.vertex_slots()), perm(m.edge_slots()), perm(m.face_slots()));
}

void one_ring(benchmark::State& state, const hedge::SurfaceMesh* m) {
  for (auto _ : state) {
    std::size_t sum = 0;
    for (hedge::Vertex v : m->vertices())
      for (hedge::Vertex w : m->vertices(v)) sum += w.idx();
    benchmark::DoNotOptimize(sum);
  }
  state.counters["acmr"] = hedge::average_cache_miss_ratio(*m, 16);
}

// ---- BM_convex_hull: quickhull (algorithms/convex_hull.h) of n random points in a unit ball
// (fixed seed), 10^3 to 10^5, and of a shard-sized set of 200 points. Needs no mesh. ----
std::vector<hedge::Vec3> ball_points(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1, 1);
  std::vector<hedge::Vec3> pts;
  while (pts.size() < n) {
    const hedge::Vec3 p{u(rng), u(rng), u(rng)};
    if (hedge::dot(p, p) <= 1) pts.push_back(p);
  }
  return pts;
}

void BM_convex_hull(benchmark::State& state) {
  const std::vector<hedge::Vec3> pts = ball_points(static_cast<std::size_t>(state.range(0)), 1);
  std::size_t hull_vertices = 0;
  for (auto _ : state) {
    hedge::ConvexHull h = hedge::convex_hull(pts);
    hull_vertices = h.mesh.n_vertices();
    benchmark::DoNotOptimize(h);
  }
  state.counters["hull_vertices"] = static_cast<double>(hull_vertices);
}
BENCHMARK(BM_convex_hull)->Arg(200)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);
// ---- BM_triangulate_polygon: one polygon of 10^3 or 10^4 corners, three shapes. ----
std::vector<hedge::Vec3d> bench_polygon(int shape, std::size_t n) {
  std::vector<hedge::Vec3d> p;
  if (shape == 0) {  // jittered circle
    hedge::SplitMix64 random(7);
    for (std::size_t i = 0; i < n; ++i) {
      const double t = 2 * 3.141592653589793 * static_cast<double>(i) / static_cast<double>(n);
      const double r = 1 + 2.0 / static_cast<double>(n) * (random.uniform() - 0.5);
      p.push_back({r * std::cos(t), r * std::sin(t), 0});
    }
  } else if (shape == 1) {  // comb: a base, then teeth up to y = 4 and notches down to y = 1
    const std::size_t teeth = (n - 2) / 2;
    p = {{0, 0, 0}, {static_cast<double>(teeth), 0, 0}};
    for (std::size_t j = teeth; j >= 1; --j) {
      p.push_back({static_cast<double>(j), 4, 0});
      p.push_back({static_cast<double>(j) - 0.5, 1, 0});
    }
    p.back() = {0, 4, 0};
  } else {  // zigzag strip, numbered from the middle of its lower side
    const std::size_t m = n / 2;
    for (std::size_t j = 0; j < m; ++j) p.push_back({static_cast<double>(j), (j % 2) - 0.3, 0});
    for (std::size_t j = m; j-- > 0;) p.push_back({static_cast<double>(j), (j % 2) + 0.3, 0});
    std::rotate(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(m / 2), p.end());
  }
  return p;
}

void BM_triangulate_polygon(benchmark::State& state, int shape) {
  const std::vector<hedge::Vec3d> p = bench_polygon(shape, static_cast<std::size_t>(state.range(0)));
  std::vector<std::array<hedge::Index, 3>> tris;
  for (auto _ : state) {
    tris.clear();
    hedge::triangulate_polygon(p, tris);
    benchmark::DoNotOptimize(tris.data());
  }
  state.counters["corners"] = static_cast<double>(p.size());
}
BENCHMARK_CAPTURE(BM_triangulate_polygon, jitter, 0)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_triangulate_polygon, comb, 1)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_triangulate_polygon, strip, 2)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void decimate_tenth(benchmark::State& state, const hedge::SurfaceMesh* input) {
  hedge::DecimateResult r;
  for (auto _ : state) {
    state.PauseTiming();
    auto m = std::make_unique<hedge::SurfaceMesh>(*input);
    state.ResumeTiming();
    r = hedge::decimate(*m, {.target_vertices = input->n_vertices() / 10});
    state.PauseTiming();
    m.reset();
    state.ResumeTiming();
  }
  state.counters["vertices"] = static_cast<double>(r.vertices);
  state.counters["max_error"] = r.max_error;
}

//! The meshes BM_fracture breaks, made or read on first use (the 1M plate takes a second).
const hedge::SurfaceMesh* fracture_input(const std::string& name, const std::string& root) {
  static std::vector<std::pair<std::string, std::unique_ptr<hedge::SurfaceMesh>>> cache;
  for (const auto& [n, m] : cache)
    if (n == name) return m.get();
  std::unique_ptr<hedge::SurfaceMesh> m;
  if (name == "plate_100k") {
    m = std::make_unique<hedge::SurfaceMesh>(hedge::build(bench::plate(224)));  // 100,352 triangles
  } else if (name == "plate_1m") {
    m = std::make_unique<hedge::SurfaceMesh>(hedge::build(bench::plate(708)));  // 1,002,528 triangles
  } else {
    const bench::Input in = bench::load_input(root + "/../shared/meshes/" + name + ".ply");
    m = std::make_unique<hedge::SurfaceMesh>(hedge::build_triangles(
        {reinterpret_cast<const hedge::Vec3*>(in.xyz.data()), in.n_vertices()}, in.tri));
  }
  cache.emplace_back(name, std::move(m));
  return cache.back().second.get();
}

//! fracture_input(), or nullptr after marking the benchmark skipped with the reason.
const hedge::SurfaceMesh* fracture_input_or_skip(benchmark::State& state, const std::string& name,
                                                 const std::string& root) {
  try {
    return fracture_input(name, root);
  } catch (const std::exception& e) {
    state.SkipWithError(("skipped: " + std::string(e.what())).c_str());
    return nullptr;
  }
}

//! The counters of both fracture benchmarks: the input's triangles, the mean shards and shard faces
//! per impact, and the median and 99th percentile of the timed calls in `seconds` (sorted here).
//! Returns false, setting nothing, when no call was timed.
bool set_fracture_counters(benchmark::State& state, std::vector<double>& seconds, double triangles,
                           double shards, double faces) {
  if (seconds.empty()) return false;
  const double n = double(seconds.size());
  std::sort(seconds.begin(), seconds.end());
  state.counters["triangles"] = triangles;
  state.counters["shards"] = shards / n;
  state.counters["faces"] = faces / n;
  state.counters["median_us"] = 1e6 * seconds[seconds.size() / 2];
  state.counters["p99_us"] = 1e6 * seconds[std::min(seconds.size() - 1, seconds.size() * 99 / 100)];
  return true;
}

void fracture_impacts(benchmark::State& state, std::string name, std::string root, bool edge_lengths) {
  const hedge::SurfaceMesh* input = fracture_input_or_skip(state, name, root);
  if (!input) return;
  auto mesh = std::make_unique<hedge::SurfaceMesh>(*input);
  auto bvh = std::make_unique<hedge::FaceBvh>(*mesh);
  std::mt19937_64 rng(1);
  hedge::FractureOptions options;
  options.material = hedge::fracture_material("glass");
  if (edge_lengths) {
    options.material.units = hedge::FractureUnits::edge_lengths;
    options.material.radius = hedge::fracture_material_radius(options.material);
  }
  double shards = 0, faces = 0;
  std::vector<double> seconds;
  hedge::FractureResult::Timings total;
  for (auto _ : state) {
    state.PauseTiming();
    if (mesh->n_faces() < input->n_faces() * 4 / 5) {
      bvh.reset();
      mesh = std::make_unique<hedge::SurfaceMesh>(*input);
      bvh = std::make_unique<hedge::FaceBvh>(*mesh);
    }
    hedge::Face f;
    do f = hedge::Face(static_cast<hedge::Index>(rng() % mesh->face_slots()));
    while (mesh->is_deleted(f));
    const hedge::Vec3 impact = hedge::face_centroid(*mesh, f);
    options.seed = rng();
    state.ResumeTiming();
    const auto start = std::chrono::steady_clock::now();
    hedge::FractureResult r = hedge::fracture(*mesh, impact, options, bvh.get());
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    state.PauseTiming();
    shards += double(r.shards.size());
    for (const hedge::Shard& s : r.shards) faces += double(s.mesh.n_faces());
    total.locate += r.seconds.locate;
    total.scatter += r.seconds.scatter;
    total.cut += r.seconds.cut;
    total.detach += r.seconds.detach;
    total.hulls += r.seconds.hulls;
    r = {};
    state.ResumeTiming();
  }
  if (!set_fracture_counters(state, seconds, double(input->n_faces()), shards, faces)) return;
  const double n = double(seconds.size());
  state.counters["locate_us"] = 1e6 * total.locate / n;
  state.counters["scatter_us"] = 1e6 * total.scatter / n;
  state.counters["cut_us"] = 1e6 * total.cut / n;
  state.counters["detach_us"] = 1e6 * total.detach / n;
  state.counters["hulls_us"] = 1e6 * total.hulls / n;
}

//! A C ABI mesh of the triangles of `m` (which has no deleted element), numbered as in `m`, with its
//! picking tree built. Null, with the error in `error`, on failure.
hedge_mesh* capi_mesh(const hedge::SurfaceMesh& m, std::string& error) {
  std::vector<float> xyz;
  xyz.reserve(3 * m.n_vertices());
  for (hedge::Vertex v : m.vertices()) {
    const hedge::Vec3 p = m.position(v);
    xyz.insert(xyz.end(), {p.x, p.y, p.z});
  }
  std::vector<std::uint32_t> indices;
  indices.reserve(3 * m.n_faces());
  for (hedge::Face f : m.faces())
    for (hedge::Vertex v : m.vertices(f)) indices.push_back(v.idx());
  hedge_mesh* mesh = nullptr;
  if (hedge_mesh_create(xyz.data(), std::uint32_t(m.n_vertices()), indices.data(),
                        std::uint32_t(indices.size()), nullptr, 0, nullptr, nullptr, nullptr, nullptr,
                        &mesh) != HEDGE_OK ||
      hedge_mesh_bvh_update(mesh, nullptr) != HEDGE_OK) {
    error = hedge_last_error();
    if (mesh) hedge_mesh_destroy(mesh);
    return nullptr;
  }
  return mesh;
}

//! The centroid of a live face of a C ABI mesh, computed as hedge::face_centroid() computes it.
bool capi_face_centroid(hedge_mesh* mesh, std::uint32_t f, float out[3]) {
  std::uint32_t corners[16], n = 0;
  if (hedge_face_vertices(mesh, f, corners, 16, &n) != HEDGE_OK || n == 0) return false;
  double c[3] = {0, 0, 0};
  for (std::uint32_t i = 0; i < n; ++i) {
    float p[3];
    if (hedge_vertex_position(mesh, corners[i], p) != HEDGE_OK) return false;
    for (int k = 0; k < 3; ++k) c[k] += double(p[k]);
  }
  for (int k = 0; k < 3; ++k) out[k] = float(c[k] / double(n));
  return true;
}

void capi_fracture_impacts(benchmark::State& state, std::string name, std::string root) {
  const hedge::SurfaceMesh* input = fracture_input_or_skip(state, name, root);
  if (!input) return;
  std::string error;
  hedge_mesh* mesh = capi_mesh(*input, error);
  hedge_fracture_options options;
  hedge_fracture_options_default(HEDGE_FRACTURE_GLASS, &options);
  options.units = HEDGE_FRACTURE_UNITS_EDGE_LENGTHS;  // as BM_fracture
  options.radius = 0;
  for (std::uint32_t i = 0; i < options.ring_count; ++i) options.radius += options.rings[i].spacing;
  std::uint32_t capacity = 0;
  for (std::uint32_t i = 0; i < options.ring_count; ++i) capacity += options.rings[i].points;
  std::vector<hedge_fracture_shard> shards(capacity);
  std::mt19937_64 rng(1);
  double broken = 0, faces = 0;
  std::vector<double> seconds;
  for (auto _ : state) {
    state.PauseTiming();
    hedge_counts counts{};
    if (mesh) hedge_mesh_counts(mesh, &counts);
    if (mesh && counts.faces < input->n_faces() * 4 / 5) {
      hedge_mesh_destroy(mesh);
      mesh = capi_mesh(*input, error);
      if (mesh) hedge_mesh_counts(mesh, &counts);
    }
    if (!mesh) {
      state.SkipWithError(("hedge_mesh_create: " + error).c_str());
      break;
    }
    std::uint32_t f = 0;
    std::int32_t deleted = 1;
    do {
      f = static_cast<std::uint32_t>(rng() % counts.face_slots);
      hedge_face_is_deleted(mesh, f, &deleted);
    } while (deleted);
    float impact[3] = {0, 0, 0};
    if (!capi_face_centroid(mesh, f, impact)) {
      state.SkipWithError(("the centroid of face " + std::to_string(f) + ": " + hedge_last_error()).c_str());
      break;
    }
    options.seed = rng();
    std::uint32_t count = 0;
    state.ResumeTiming();
    const auto start = std::chrono::steady_clock::now();
    const hedge_status status =
        hedge_mesh_fracture(mesh, impact[0], impact[1], impact[2], &options, shards.data(), capacity, &count);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    state.PauseTiming();
    if (status != HEDGE_OK) {
      state.SkipWithError(("hedge_mesh_fracture: " + std::string(hedge_last_error())).c_str());
      break;
    }
    broken += double(count);
    for (std::uint32_t i = 0; i < count; ++i) {
      hedge_counts c{};
      hedge_mesh_counts(shards[i].mesh, &c);
      faces += double(c.faces);
      hedge_mesh_destroy(shards[i].mesh);
      if (shards[i].hull) hedge_mesh_destroy(shards[i].hull);
    }
    state.ResumeTiming();
  }
  if (mesh) hedge_mesh_destroy(mesh);
  set_fracture_counters(state, seconds, double(input->n_faces()), broken, faces);
}

using bench::grid_sphere;

void fracture_solid_impacts(benchmark::State& state, int n, float radius, unsigned points) {
  static std::vector<std::pair<std::pair<int, float>, std::unique_ptr<hedge::SurfaceMesh>>> cache;
  const hedge::SurfaceMesh* input = nullptr;
  for (const auto& [k, m] : cache)
    if (k == std::make_pair(n, radius)) input = m.get();
  if (!input) {
    cache.emplace_back(std::make_pair(n, radius),
                       std::make_unique<hedge::SurfaceMesh>(grid_sphere(n, radius)));
    input = cache.back().second.get();
  }
  auto mesh = std::make_unique<hedge::SurfaceMesh>(*input);
  auto bvh = std::make_unique<hedge::FaceBvh>(*mesh);
  std::mt19937_64 rng(1);
  hedge::SolidFractureOptions options;
  options.material.name = "bench";
  options.material.rings = {{points / 4, 1, 0.5}, {points - points / 4, 1, 0.5}};
  options.radius = 0.5;
  options.hulls = true;
  double pieces = 0;
  std::vector<double> seconds;
  hedge::SolidFractureResult::Timings total;
  int strikes = 0;
  for (auto _ : state) {
    state.PauseTiming();
    if (++strikes % 4 == 0) {
      bvh.reset();
      mesh = std::make_unique<hedge::SurfaceMesh>(*input);
      bvh = std::make_unique<hedge::FaceBvh>(*mesh);
    }
    std::normal_distribution<double> g;
    const hedge::Vec3 dir = {float(g(rng)), float(g(rng)), float(g(rng))};
    const auto near = bvh->closest_point(dir);
    options.seed = rng();
    state.ResumeTiming();
    const auto t0 = std::chrono::steady_clock::now();
    hedge::SolidFractureResult r;
    try {
      r = hedge::fracture_solid(*mesh, near->point, options, bvh.get());
    } catch (const hedge::InvalidInputError&) {
      // A refused strike (about 1%) leaves the mesh as it was; it is timed all the same.
    }
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    state.PauseTiming();
    pieces += double(r.pieces.size());
    total.locate += r.seconds.locate;
    total.cells += r.seconds.cells;
    total.clip += r.seconds.clip;
    total.cap += r.seconds.cap;
    total.assemble += r.seconds.assemble;
    total.per_piece += r.seconds.per_piece;
    r = {};
    state.ResumeTiming();
  }
  if (set_fracture_counters(state, seconds, double(input->n_faces()), pieces, 0)) {
    const double k = 1e6 / double(seconds.size());
    state.counters["pieces"] = pieces / double(seconds.size());
    state.counters["locate_us"] = total.locate * k;
    state.counters["cells_us"] = total.cells * k;
    state.counters["clip_us"] = total.clip * k;
    state.counters["cap_us"] = total.cap * k;
    state.counters["assemble_us"] = total.assemble * k;
    state.counters["per_piece_us"] = total.per_piece * k;
  }
}

void BM_convex_hull_pieces(benchmark::State& state) {
  const auto points = static_cast<unsigned>(state.range(0));
  hedge::SurfaceMesh mesh = grid_sphere(91);
  hedge::FaceBvh bvh(mesh);
  std::mt19937_64 rng(1);
  std::normal_distribution<double> g;
  const hedge::Vec3 dir = {float(g(rng)), float(g(rng)), float(g(rng))};
  hedge::SolidFractureOptions options;
  options.material.name = "bench";
  options.material.rings = {{points / 4, 1, 0.5}, {points - points / 4, 1, 0.5}};
  options.radius = 0.5;
  options.seed = rng();
  const hedge::SolidFractureResult r =
      hedge::fracture_solid(mesh, bvh.closest_point(dir)->point, options, &bvh);
  std::vector<std::vector<hedge::Vec3>> sets;
  std::size_t n_points = 0;
  for (const hedge::SolidPiece& piece : r.pieces) {
    std::vector<hedge::Vec3>& set = sets.emplace_back();
    for (hedge::Vertex v : piece.mesh.vertices()) set.push_back(piece.mesh.position(v));
    n_points += set.size();
  }
  for (auto _ : state)
    for (const std::vector<hedge::Vec3>& set : sets) {
      hedge::ConvexHull h = hedge::convex_hull(set);
      benchmark::DoNotOptimize(h);
    }
  state.counters["pieces"] = double(sets.size());
  state.counters["points"] = double(n_points) / double(sets.size());
}
BENCHMARK(BM_convex_hull_pieces)->Arg(64)->Arg(200)->Unit(benchmark::kMicrosecond);

void register_fracture(const std::string& root) {
  struct Sphere {
    const char* name;
    int n;
    float radius;
  };
  for (const Sphere& sphere : {Sphere{"sphere_100k", 91, 1.0f}, Sphere{"sphere_1m", 289, 1.0f},
                               Sphere{"sphere_1m_r3", 289, std::sqrt(10.0f)}})
    for (unsigned points : {64u, 200u})
      benchmark::RegisterBenchmark(
          (std::string("BM_fracture_solid/") + sphere.name + "/" + std::to_string(points)).c_str(),
          fracture_solid_impacts, sphere.n, sphere.radius, points)
          ->Unit(benchmark::kMillisecond)
          ->MeasureProcessCPUTime()
          ->Iterations(24);
  // The bars are set at 32 and 100 pieces: the break point counts that give about as many
  // on sphere_100k.
  for (unsigned points : {52u, 182u})
    benchmark::RegisterBenchmark(
        (std::string("BM_fracture_solid/sphere_100k/") + std::to_string(points)).c_str(),
        fracture_solid_impacts, 91, 1.0f, points)
        ->Unit(benchmark::kMillisecond)
        ->MeasureProcessCPUTime()
        ->Iterations(24);
  for (const char* name : {"plate_100k", "plate_1m", "igea"}) {
    benchmark::RegisterBenchmark((std::string("BM_fracture/") + name).c_str(), fracture_impacts,
                                 std::string(name), root, true)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("BM_fracture_diagonal/") + name).c_str(), fracture_impacts,
                                 std::string(name), root, false)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("BM_capi_fracture/") + name).c_str(), capi_fracture_impacts,
                                 std::string(name), root)
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  std::string root;
  std::vector<std::string> specs;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--root" && i + 1 < argc)
      root = argv[++i];
    else
      specs.push_back(a);
  }
  register_fracture(bench::find_root(root));
  if (specs.empty()) {
    std::string note;
    specs = bench::default_mesh_specs(bench::find_root(root), note);
    std::cerr << note << "\n";
    if (specs.empty()) {
      benchmark::RunSpecifiedBenchmarks();
      benchmark::Shutdown();
      return 0;
    }
  }

  static const bench::Backend backend = bench::hedge_backend();
  static std::vector<std::unique_ptr<Loaded>> meshes;
  for (const std::string& spec : specs) {
    auto l = std::make_unique<Loaded>();
    try {
      l->input = bench::load_spec(spec);
      l->scratch.resize(l->input);
      l->reference = backend.build(l->input);
    } catch (const std::exception& e) {
      std::cerr << spec << ": skipped: " << e.what() << "\n";
      continue;
    }
    for (const auto& [key, impl] : backend.ops)
      benchmark::RegisterBenchmark(("BM_" + key + "/" + l->input.name).c_str(), run_op, &impl, l.get())
          ->Unit(benchmark::kMillisecond);
    // The element order's effect on circulation.
    static std::vector<std::unique_ptr<hedge::SurfaceMesh>> orders;
    auto as_loaded = std::make_unique<hedge::SurfaceMesh>(hedge::build_triangles(
        {reinterpret_cast<const hedge::Vec3*>(l->input.xyz.data()), l->input.n_vertices()}, l->input.tri));
    const hedge::SurfaceMesh* loaded_mesh = as_loaded.get();
    auto shuffled = std::make_unique<hedge::SurfaceMesh>(*as_loaded);
    shuffle(*shuffled, 1);
    auto spatial = std::make_unique<hedge::SurfaceMesh>(*shuffled);
    hedge::reorder(*spatial, hedge::Ordering::spatial);
    auto vertex_cache = std::make_unique<hedge::SurfaceMesh>(*shuffled);
    hedge::reorder(*vertex_cache, hedge::Ordering::vertex_cache);
    for (auto* m : {&as_loaded, &shuffled, &spatial, &vertex_cache}) {
      const char* what = m == &as_loaded  ? "as_loaded"
                         : m == &shuffled ? "shuffled"
                         : m == &spatial  ? "spatial"
                                          : "vertex_cache";
      benchmark::RegisterBenchmark(("BM_one_ring_order/" + l->input.name + "/" + what).c_str(), one_ring,
                                   m->get())
          ->Unit(benchmark::kMillisecond);
      orders.push_back(std::move(*m));
    }
    benchmark::RegisterBenchmark(("BM_decimate/" + l->input.name).c_str(), decimate_tenth, loaded_mesh)
        ->Unit(benchmark::kMillisecond);
    meshes.push_back(std::move(l));
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
