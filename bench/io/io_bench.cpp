// Parsing speed of hedge's readers against tinyobjloader and assimp. Every reader parses the same
// bytes from memory, so file-system effects are left out; each benchmark reports the vertex and
// face counts it produced, which shows that the readers did comparable work.

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <istream>
#include <map>
#include <streambuf>
#include <string>
#include <vector>

#include "hedge/io/io.h"

#ifdef HEDGE_BENCH_TINYOBJLOADER
#include <tiny_obj_loader.h>
#endif
#ifdef HEDGE_BENCH_ASSIMP
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#endif

namespace {

struct Case {
  std::string format;  // obj, ply, off, stl
  std::string file;
};

// A read-only stream over bytes already in memory: tinyobjloader reads from a std::istream, and
// copying the file into a stringstream would charge it for a copy the other readers do not make.
class MemoryBuffer : public std::streambuf {
 public:
  explicit MemoryBuffer(const std::string& s) {
    char* p = const_cast<char*>(s.data());
    setg(p, p, p + s.size());
  }
};

void bench_hedge(benchmark::State& state, const std::string& bytes, hedge::FileFormat format) {
  std::size_t vertices = 0, faces = 0;
  for (auto _ : state) {
    hedge::IndexedMesh m = hedge::read_indexed(bytes, format);
    vertices = m.positions.size();
    faces = m.face_count();
    benchmark::DoNotOptimize(m.indices.data());
  }
  state.counters["V"] = static_cast<double>(vertices);
  state.counters["F"] = static_cast<double>(faces);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
}

#ifdef HEDGE_BENCH_TINYOBJLOADER
void bench_tinyobj(benchmark::State& state, const std::string& bytes) {
  std::size_t vertices = 0, faces = 0;
  for (auto _ : state) {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    MemoryBuffer buffer(bytes);
    std::istream in(&buffer);
    // No triangulation and no colour fallback: the least work it can be asked to do.
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, nullptr, false, false)) {
      state.SkipWithError(("tinyobjloader failed: " + err).c_str());
      return;
    }
    vertices = attrib.vertices.size() / 3;
    faces = 0;
    for (const auto& s : shapes) faces += s.mesh.num_face_vertices.size();
    benchmark::DoNotOptimize(attrib.vertices.data());
  }
  state.counters["V"] = static_cast<double>(vertices);
  state.counters["F"] = static_cast<double>(faces);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
}
#endif

#ifdef HEDGE_BENCH_ASSIMP
void bench_assimp(benchmark::State& state, const std::string& bytes, const std::string& hint) {
  Assimp::Importer importer;
  std::size_t vertices = 0, faces = 0;
  for (auto _ : state) {
    // No post-processing steps: parsing and building its scene only.
    const aiScene* scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, hint.c_str());
    if (scene == nullptr) {
      state.SkipWithError((std::string("assimp failed: ") + importer.GetErrorString()).c_str());
      return;
    }
    vertices = faces = 0;
    for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
      vertices += scene->mMeshes[i]->mNumVertices;
      faces += scene->mMeshes[i]->mNumFaces;
    }
    benchmark::DoNotOptimize(scene);
  }
  state.counters["V"] = static_cast<double>(vertices);
  state.counters["F"] = static_cast<double>(faces);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
}
#endif

}  // namespace

int main(int argc, char** argv) {
  const char* env = std::getenv("HEDGE_MESH_DIR");
  const std::string dir = env != nullptr ? env : HEDGE_BENCH_MESH_DIR;
  const std::vector<Case> cases = {
      {"obj", "armadillo.obj"},          // triangles, v and f only
      {"obj", "spot_triangulated.obj"},  // with texture coordinates
      {"ply", "igea.ply"},               // binary, triangle strips
      {"ply", "horse.ply"},              // binary, faces and per-vertex normals
      {"ply", "bun_zipper_res2.ply"},    // ascii
      {"off", "bunny.off"},
      {"stl", "cube1Binary.stl"},
  };
  // The bytes outlive the benchmarks that refer to them.
  std::map<std::string, std::string> contents;
  for (const Case& c : cases) {
    const std::string path = dir + "/" + c.file;
    if (!std::filesystem::exists(path)) {
      std::fprintf(stderr, "skipping %s: not found (set HEDGE_MESH_DIR)\n", path.c_str());
      continue;
    }
    const std::string& bytes = contents[c.file] = hedge::read_file(path);
    const hedge::FileFormat format = hedge::format_from_path(path);
    const std::string stem = c.format + "/" + c.file.substr(0, c.file.find('.'));
    benchmark::RegisterBenchmark((stem + "/hedge").c_str(), bench_hedge, std::cref(bytes), format)
        ->Unit(benchmark::kMillisecond);
#ifdef HEDGE_BENCH_TINYOBJLOADER
    if (c.format == "obj")
      benchmark::RegisterBenchmark((stem + "/tinyobjloader").c_str(), bench_tinyobj, std::cref(bytes))
          ->Unit(benchmark::kMillisecond);
#endif
#ifdef HEDGE_BENCH_ASSIMP
    benchmark::RegisterBenchmark((stem + "/assimp").c_str(), bench_assimp, std::cref(bytes), c.format)
        ->Unit(benchmark::kMillisecond);
#endif
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
