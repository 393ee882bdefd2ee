// The C++ side of bench/python/bench_binding.py: times build_triangles on the arrays the script
// wrote (raw float32 positions and uint32 triangles), so that Mesh.from_arrays can be compared with
// the library on the same input in the same build.
//   build_reference POSITIONS.f32 TRIANGLES.u32 RUNS
// Prints the median time in milliseconds.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <vector>

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

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: build_reference POSITIONS.f32 TRIANGLES.u32 RUNS\n");
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
  std::nth_element(ms.begin(), ms.begin() + static_cast<std::ptrdiff_t>(ms.size() / 2), ms.end());
  std::printf("%.3f\n", ms[ms.size() / 2]);
  return 0;
}
