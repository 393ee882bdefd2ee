// The C++ side of bench/python/bench_binding.py: times build_triangles on the arrays the script
// wrote (raw float32 positions and uint32 triangles), so that Mesh.from_arrays can be compared with
// the library on the same input in the same build; with a third file of rays (6 float32 each:
// origin, direction), also times FaceBvh::first_hit over all of them on the built mesh, as
// Mesh.ray_cast walks them. It also times the one-rings of every vertex gathered into offsets and
// neighbours, as Mesh.one_rings() returns them.
//   build_reference POSITIONS.f32 TRIANGLES.u32 RUNS [RAYS.f32]
// Prints the median times in milliseconds: the build, the one-rings, then the rays.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <vector>

#include "hedge/algorithms/locate.h"
#include "hedge/core/build.h"

namespace {

template <typename T>
std::vector<T> read_raw(const char* path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<T> out(bytes.size() / sizeof(T));
  std::copy(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(out.size() * sizeof(T)),
            reinterpret_cast<char*>(out.data()));
  return out;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 && argc != 5) {
    std::fprintf(stderr, "usage: build_reference POSITIONS.f32 TRIANGLES.u32 RUNS [RAYS.f32]\n");
    return 2;
  }
  const std::vector<hedge::Vec3> positions = read_raw<hedge::Vec3>(argv[1]);
  const std::vector<std::uint32_t> triangles = read_raw<std::uint32_t>(argv[2]);
  const int runs = std::max(1, std::atoi(argv[3]));
  hedge::BuildOptions options;
  options.policy = hedge::TopologyPolicy::repair;
  std::vector<double> ms;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    hedge::BuildReport report;
    const hedge::SurfaceMesh mesh = hedge::build_triangles(positions, triangles, options, &report);
    const auto t1 = std::chrono::steady_clock::now();
    if (mesh.n_faces() != triangles.size() / 3) return 1;
    ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  std::printf("%.3f\n", median(ms));
  const hedge::SurfaceMesh mesh = hedge::build_triangles(positions, triangles, options);
  ms.clear();
  for (int i = 0; i < runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<std::int64_t> offsets(mesh.vertex_slots() + 1, 0);
    for (const hedge::Vertex v : mesh.vertices())
      for ([[maybe_unused]] const hedge::Halfedge h : mesh.halfedges(v)) ++offsets[v.idx() + 1];
    for (std::size_t v = 0; v < mesh.vertex_slots(); ++v) offsets[v + 1] += offsets[v];
    std::vector<std::int32_t> neighbours(static_cast<std::size_t>(offsets.back()));
    for (const hedge::Vertex v : mesh.vertices()) {
      std::int64_t k = offsets[v.idx()];
      for (const hedge::Halfedge h : mesh.halfedges(v))
        neighbours[static_cast<std::size_t>(k++)] = static_cast<std::int32_t>(mesh.to_vertex(h).idx());
    }
    const auto t1 = std::chrono::steady_clock::now();
    if (neighbours.size() != 2 * mesh.n_edges()) return 1;
    ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  std::printf("%.3f\n", median(ms));
  if (argc == 5) {
    const std::vector<float> rays = read_raw<float>(argv[4]);
    const hedge::FaceBvh bvh(mesh);
    std::vector<std::int32_t> faces(rays.size() / 6);
    ms.clear();
    for (int i = 0; i < runs; ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      for (std::size_t r = 0; r < faces.size(); ++r) {
        const float* q = &rays[6 * r];
        const auto hit = bvh.first_hit(hedge::Vec3{q[0], q[1], q[2]}, hedge::Vec3{q[3], q[4], q[5]});
        faces[r] = hit ? static_cast<std::int32_t>(hit->face.idx()) : -1;
      }
      const auto t1 = std::chrono::steady_clock::now();
      ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    std::printf("%.3f\n", median(ms));
  }
  return 0;
}
