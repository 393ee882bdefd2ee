// Replays the first strikes of hedge_bench's BM_fracture_solid/sphere_100k/<points> exactly as the
// benchmark makes them (the same sphere, material, radius, impact points and seeds, the mesh and its
// picking tree restored before every fourth strike), on one thread unless told otherwise, and
// prints per strike the piece count and a hash of the result (every piece's mesh, positions and
// half-edge links, its mass properties and hull, the bonds, and the remaining mesh), so that two
// builds can be compared for bit-identity and their instructions counted stage by stage:
//
//   solid_strike_replay [points=64] [strikes=8] [threads=1]
//
// clang-format off
//   valgrind --tool=callgrind --toggle-collect='hedge::fracture_solid*' build/bench/bench/solid_strike_replay 64 8
//   callgrind_annotate --inclusive=yes callgrind.out.<pid>
// clang-format on
//
// (64 break points, 8 strikes), then divide a function's inclusive count by the strikes for its
// cost per strike. threads=0 lets the strike use every core, as the benchmark does; the hashes must
// not change with it.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>

#include "grid_sphere.h"
#include "hedge/algorithms/fracture_solid.h"
#include "hedge/algorithms/locate.h"
#include "hedge/core/threads.h"

namespace {

//! FNV-1a, 64 bits, over raw bytes.
struct Hash {
  std::uint64_t h = 1469598103934665603ull;
  void bytes(const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 1099511628211ull;
  }
  template <typename T>
  void add(const T& v) {
    bytes(&v, sizeof v);
  }
};

//! Slot counts, deleted flags and, for every live element, its links and position.
void add_mesh(Hash& h, const hedge::SurfaceMesh& m) {
  h.add(std::uint64_t(m.vertex_slots()));
  h.add(std::uint64_t(m.halfedge_slots()));
  h.add(std::uint64_t(m.face_slots()));
  for (std::uint32_t i = 0; i < m.vertex_slots(); ++i) {
    const hedge::Vertex v(i);
    const bool dead = m.is_deleted(v);
    h.add(dead);
    if (dead) continue;
    const hedge::Vec3& p = m.position(v);
    h.add(p.x), h.add(p.y), h.add(p.z);
    h.add(m.halfedge(v).idx());
  }
  for (std::uint32_t i = 0; i < m.halfedge_slots(); ++i) {
    const hedge::Halfedge e(i);
    const bool dead = m.is_deleted(e);
    h.add(dead);
    if (dead) continue;
    h.add(m.to_vertex(e).idx()), h.add(m.next(e).idx()), h.add(m.face(e).idx());
  }
  for (std::uint32_t i = 0; i < m.face_slots(); ++i) {
    const hedge::Face f(i);
    const bool dead = m.is_deleted(f);
    h.add(dead);
    if (!dead) h.add(m.halfedge(f).idx());
  }
}

void add_result(Hash& h, const hedge::SolidFractureResult& r) {
  h.add(std::uint64_t(r.pieces.size()));
  for (const hedge::SolidPiece& piece : r.pieces) {
    add_mesh(h, piece.mesh);
    h.add(piece.centroid), h.add(piece.volume), h.add(piece.cap_area);
    h.add(piece.mass.mass), h.add(piece.mass.volume), h.add(piece.mass.centre_of_mass);
    h.add(piece.mass.inertia), h.add(piece.mass.principal_moments), h.add(piece.mass.principal_axes);
    add_mesh(h, piece.hull.mesh);
    h.bytes(piece.hull.input_index.data(), piece.hull.input_index.size() * sizeof(std::uint32_t));
  }
  h.add(std::uint64_t(r.bonds.size()));
  for (const hedge::SolidBond& b : r.bonds)
    h.add(std::uint64_t(b.a)), h.add(std::uint64_t(b.b)), h.add(b.area);
  h.add(r.impact_face.idx()), h.add(r.impact_point), h.add(r.radius);
}

}  // namespace

int main(int argc, char** argv) {
  const unsigned points = argc > 1 ? unsigned(std::atoi(argv[1])) : 64;
  const int strikes = argc > 2 ? std::atoi(argv[2]) : 8;
  hedge::set_max_threads(argc > 3 ? unsigned(std::atoi(argv[3])) : 1);

  // As fracture_solid_impacts() in hedge_bench.cpp, for sphere_100k.
  const hedge::SurfaceMesh input = bench::grid_sphere(91, 1.0f);
  auto mesh = std::make_unique<hedge::SurfaceMesh>(input);
  auto bvh = std::make_unique<hedge::FaceBvh>(*mesh);
  std::mt19937_64 rng(1);
  hedge::SolidFractureOptions options;
  options.material.name = "bench";
  options.material.rings = {{points / 4, 1, 0.5}, {points - points / 4, 1, 0.5}};
  options.radius = 0.5;
  options.hulls = true;
  Hash all;
  for (int strike = 1; strike <= strikes; ++strike) {
    if (strike % 4 == 0) {
      bvh.reset();
      mesh = std::make_unique<hedge::SurfaceMesh>(input);
      bvh = std::make_unique<hedge::FaceBvh>(*mesh);
    }
    std::normal_distribution<double> g;
    const hedge::Vec3 dir = {float(g(rng)), float(g(rng)), float(g(rng))};
    const auto near = bvh->closest_point(dir);
    options.seed = rng();
    hedge::SolidFractureResult r;
    bool refused = false;
    try {
      r = hedge::fracture_solid(*mesh, near->point, options, bvh.get());
    } catch (const hedge::InvalidInputError&) {
      refused = true;  // the mesh is as it was, as in the benchmark
    }
    Hash h;
    h.add(refused);
    add_result(h, r);
    add_mesh(h, *mesh);
    all.add(h.h);
    std::printf("strike %d: %zu pieces%s, hash %016llx\n", strike, r.pieces.size(),
                refused ? " (refused)" : "", static_cast<unsigned long long>(h.h));
  }
  std::printf("all %d strikes of %u points: hash %016llx\n", strikes, points,
              static_cast<unsigned long long>(all.h));
}
