// Table 1 of the original project, measured: memory, build time and the eight adjacency queries of
// the indexed mesh, the triangle-neighbour structure, the winged-edge mesh and hedge's half-edge
// mesh, on real meshes and on a subdivision series from ~1k to ~1M triangles.
//
// Usage: hedge_structures_bench [--root DIR] [--doc FILE] [--svg FILE] [--quick] [--no-write | --write]
//   --root      the repository root (default "."): meshes are read from DIR/data and, when present,
//               DIR/../shared/meshes; --doc and --svg are relative to it
//   --doc       markdown file whose generated section is replaced (default docs/structures.md)
//   --svg       plot to write (default docs/structures_scaling.svg)
//   --quick     fewer repeats and a smaller series, for a smoke test; implies --no-write
//   --no-write  print the markdown to stdout instead of writing files
//   --write     write the files even with --quick (give it --doc and --svg elsewhere)
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "hedge/io/io.h"
#include "report.h"
#include "support/structures/edge_table.h"
#include "support/structures/half_edge_view.h"
#include "support/structures/indexed_triangles.h"
#include "support/structures/queries.h"
#include "support/structures/subdivide.h"
#include "support/structures/triangle_neighbors.h"
#include "support/structures/winged_edge.h"

namespace fs = std::filesystem;
using namespace hedge::structures;
using hedge::Index;

namespace {

struct Config {
  fs::path root = ".";
  fs::path doc = "docs/structures.md";
  fs::path svg = "docs/structures_scaling.svg";
  bool write = true;
  int repeats = 7;
  double min_sample_ms = 10;
  std::size_t max_series_faces = 1'200'000;
  //! Corner reads one pass of an exhaustive search may cost: sets the sample size.
  double scan_budget = 2e7;
  std::size_t min_scan_samples = 32;
};

// Real meshes: the repository's small ones, then larger shared ones when present.
constexpr const char* kMeshes[] = {
    "data/bob_small.ply",         "data/anchor.off",
    "data/spot_triangulated.obj", "../shared/meshes/fandisk.off",
    "../shared/meshes/bunny.off", "../shared/meshes/armadillo.obj",
    "../shared/meshes/igea.ply",
};
constexpr const char* kSeriesBase = "data/anchor.off";
constexpr const char* kReferenceMesh = "bunny.off";

volatile std::uint64_t g_sink = 0;

//! Consumes each answer element as Google Benchmark's DoNotOptimize does: the value must exist
//! in a register, so the compiler can neither drop a query nor fold a loop of queries into
//! closed-form arithmetic, yet nothing is stored.
struct Sink {
  void operator()(Index i) const { asm volatile("" : : "r"(i)); }
  void operator()(VertexPair p) const { asm volatile("" : : "r"(p.a), "r"(p.b)); }
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

//! CPU time of this thread in nanoseconds. On a shared machine the process is descheduled for
//! whole time slices; wall-clock samples would count those, CPU time does not.
double thread_cpu_ns() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
}

//! Median over cfg.repeats samples of the CPU time per item of `pass` (which handles `items`
//! items). Each sample repeats the pass until it lasts at least cfg.min_sample_ms.
template <typename Pass>
double time_per_item(Pass&& pass, std::size_t items, const Config& cfg) {
  double t0 = thread_cpu_ns();
  pass();  // warm-up, and the calibration of the pass count
  const double once = std::max(thread_cpu_ns() - t0, 1.0);
  const auto passes = static_cast<std::size_t>(std::max(1.0, std::ceil(cfg.min_sample_ms * 1e6 / once)));
  std::vector<double> samples;
  for (int r = 0; r < cfg.repeats; ++r) {
    t0 = thread_cpu_ns();
    for (std::size_t i = 0; i < passes; ++i) pass();
    samples.push_back((thread_cpu_ns() - t0) / double(passes * std::max<std::size_t>(items, 1)));
  }
  return median(samples);
}

template <typename T>
std::vector<T> seeded_sample(const std::vector<T>& all, std::size_t k, std::uint32_t seed) {
  if (k >= all.size()) return all;
  std::vector<T> v = all;
  std::mt19937 rng(seed);
  for (std::size_t i = 0; i < k; ++i) {  // partial Fisher-Yates
    std::uniform_int_distribution<std::size_t> pick(i, v.size() - 1);
    std::swap(v[i], v[pick(rng)]);
  }
  v.resize(k);
  return v;
}

template <typename S>
constexpr Structure structure_of() {
  if constexpr (std::is_same_v<S, IndexedTriangles>)
    return Structure::indexed;
  else if constexpr (std::is_same_v<S, TriangleNeighbors>)
    return Structure::triangle_neighbors;
  else if constexpr (std::is_same_v<S, WingedEdge>)
    return Structure::winged_edge;
  else
    return Structure::half_edge;
}

template <typename Input, typename Call>
QueryTiming time_query(const std::vector<Input>& all, bool exhaustive, std::size_t n_corners,
                       std::uint32_t seed, const Config& cfg, Call&& call) {
  QueryTiming t;
  std::size_t k = all.size();
  if (exhaustive) {
    k = std::max(cfg.min_scan_samples,
                 static_cast<std::size_t>(cfg.scan_budget / double(std::max<std::size_t>(n_corners, 1))));
    t.sampled = k < all.size();
  }
  const std::vector<Input> chosen = seeded_sample(all, k, seed);
  t.queries = chosen.size();
  t.ns = time_per_item(
      [&] {
        Sink sink;
        for (const Input& x : chosen) call(x, sink);
      },
      chosen.size(), cfg);
  return t;
}

template <typename S>
StructureResult measure(const TriangleArrays& mesh, const Config& cfg) {
  StructureResult r;
  const std::size_t si = static_cast<std::size_t>(structure_of<S>());
  try {
    S s = S::build(mesh.positions, mesh.triangles);
    r.build_ns = time_per_item(
        [&] {
          S t = S::build(mesh.positions, mesh.triangles);
          g_sink = g_sink + t.n_faces();
        },
        1, cfg);
    if constexpr (std::is_same_v<S, HalfEdgeView>) s.shrink_to_fit();
    r.bytes = s.memory_bytes();

    std::vector<Index> vertices(mesh.n_vertices()), faces(mesh.n_faces());
    std::iota(vertices.begin(), vertices.end(), Index{0});
    std::iota(faces.begin(), faces.end(), Index{0});
    const auto edges = s.edge_list();
    const std::size_t corners = mesh.triangles.size();
    for (std::size_t qi = 0; qi < kQueryCount; ++qi) {
      const bool exhaustive = kExpectedGrowth[si][qi] == Growth::linear;
      const auto seed = static_cast<std::uint32_t>(20240 + qi);
      auto timed = [&](const auto& inputs, auto&& call) {
        r.queries[qi] = time_query(inputs, exhaustive, corners, seed, cfg, call);
      };
      switch (kQueries[qi]) {
        case Query::edge_vertices:
          timed(edges, [&](auto e, Sink& k) { s.edge_vertices(e, k); });
          break;
        case Query::edge_faces:
          timed(edges, [&](auto e, Sink& k) { s.edge_faces(e, k); });
          break;
        case Query::edge_edges:
          timed(edges, [&](auto e, Sink& k) { s.edge_adjacent_edges(e, k); });
          break;
        case Query::vertex_edges:
          timed(vertices, [&](Index v, Sink& k) { s.vertex_edges(v, k); });
          break;
        case Query::vertex_faces:
          timed(vertices, [&](Index v, Sink& k) { s.vertex_faces(v, k); });
          break;
        case Query::face_edges:
          timed(faces, [&](Index f, Sink& k) { s.face_edges(f, k); });
          break;
        case Query::face_vertices:
          timed(faces, [&](Index f, Sink& k) { s.face_vertices(f, k); });
          break;
        case Query::face_faces:
          timed(faces, [&](Index f, Sink& k) { s.face_faces(f, k); });
          break;
      }
    }
    r.ok = true;
  } catch (const std::exception& e) {
    r.ok = false;
    r.error = e.what();
  }
  return r;
}

MeshResult measure_mesh(const std::string& label, bool series, const TriangleArrays& mesh,
                        const Config& cfg) {
  MeshResult m;
  m.label = label;
  m.series = series;
  m.n_vertices = mesh.n_vertices();
  m.n_faces = mesh.n_faces();
  const EdgeTable table = match_edges(mesh.triangles, mesh.n_vertices());
  m.n_edges = table.n_edges();
  m.boundary_edges = static_cast<std::size_t>(
      std::count(table.opposite.begin(), table.opposite.end(), hedge::kInvalidIndex));
  std::fprintf(stderr, "  %-28s %9zu V %9zu F:", label.c_str(), m.n_vertices, m.n_faces);
  m.structures[0] = measure<IndexedTriangles>(mesh, cfg);
  std::fprintf(stderr, " indexed");
  m.structures[1] = measure<TriangleNeighbors>(mesh, cfg);
  std::fprintf(stderr, " tns");
  m.structures[2] = measure<WingedEdge>(mesh, cfg);
  std::fprintf(stderr, " wem");
  m.structures[3] = measure<HalfEdgeView>(mesh, cfg);
  std::fprintf(stderr, " hedge\n");
  for (const StructureResult& r : m.structures)
    if (!r.ok) std::fprintf(stderr, "    not built: %s\n", r.error.c_str());
  return m;
}

//! Loads a triangle mesh; an empty optional-like result (no faces) with a reason on failure.
bool load_triangles(const fs::path& path, TriangleArrays& out, std::string& why) {
  try {
    hedge::IndexedMesh in = hedge::read_indexed_file(path.string());
    if (!in.is_triangles() &&
        std::any_of(in.face_sizes.begin(), in.face_sizes.end(), [](std::uint32_t n) { return n != 3; })) {
      why = "not a triangle mesh";
      return false;
    }
    out.positions = std::move(in.positions);
    out.triangles = std::move(in.indices);
    match_edges(out.triangles, out.n_vertices());  // the structures need an oriented manifold
    return true;
  } catch (const std::exception& e) {
    why = e.what();
    return false;
  }
}

std::string cpu_name() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      std::string name = line.substr(colon + 1);
      name.erase(0, name.find_first_not_of(' '));
      return name;
    }
  return "unknown CPU";
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + p.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const fs::path& p, const std::string& text) {
  const fs::path tmp = p.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  fs::rename(tmp, p);
}

int usage() {
  std::fprintf(stderr,
               "usage: hedge_structures_bench [--root DIR] [--doc FILE] [--svg FILE] [--quick] [--no-write | "
               "--write]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  Config cfg;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
    if (a == "--root" || a == "--doc" || a == "--svg") {
      const char* v = value();
      if (!v) return usage();
      (a == "--root" ? cfg.root : a == "--doc" ? cfg.doc : cfg.svg) = v;
    } else if (a == "--quick") {
      cfg.repeats = 3;
      cfg.min_sample_ms = 2;
      cfg.max_series_faces = 70'000;
      cfg.write = false;
    } else if (a == "--no-write") {
      cfg.write = false;
    } else if (a == "--write") {
      cfg.write = true;
    } else {
      return usage();
    }
  }

  RunInfo info;
  info.cpu = cpu_name();
#if defined(__clang__)
  info.compiler = std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  info.compiler = std::string("g++ ") + __VERSION__;
#else
  info.compiler = "an unknown compiler";
#endif
  info.repeats = cfg.repeats;
  info.min_sample_ms = cfg.min_sample_ms;

  std::vector<MeshResult> meshes, series;
  std::fprintf(stderr, "real meshes:\n");
  for (const char* rel : kMeshes) {
    TriangleArrays mesh;
    std::string why;
    const fs::path path = cfg.root / rel;
    const std::string label = fs::path(rel).filename().string();
    if (!fs::exists(path)) {
      std::fprintf(stderr, "  %-28s absent, skipped\n", label.c_str());
      continue;
    }
    if (!load_triangles(path, mesh, why)) {
      std::fprintf(stderr, "  %-28s skipped: %s\n", label.c_str(), why.c_str());
      continue;
    }
    meshes.push_back(measure_mesh(label, false, mesh, cfg));
  }
  info.reference = kReferenceMesh;
  if (std::none_of(meshes.begin(), meshes.end(),
                   [](const MeshResult& m) { return m.label == kReferenceMesh; })) {
    // The largest mesh measured stands in for the reference when the shared meshes are absent.
    auto largest =
        std::max_element(meshes.begin(), meshes.end(),
                         [](const MeshResult& a, const MeshResult& b) { return a.n_faces < b.n_faces; });
    info.reference = largest == meshes.end() ? "" : largest->label;
  }

  std::fprintf(stderr, "subdivision series:\n");
  {
    TriangleArrays base;
    std::string why;
    if (!load_triangles(cfg.root / kSeriesBase, base, why)) {
      std::fprintf(stderr, "cannot load the series base %s: %s\n", kSeriesBase, why.c_str());
      return 1;
    }
    info.series_base = fs::path(kSeriesBase).filename().string();
    for (int level = 0; base.n_faces() <= cfg.max_series_faces; ++level) {
      const std::string label = info.series_base + " ×4^" + std::to_string(level);
      series.push_back(measure_mesh(label, true, base, cfg));
      if (base.n_faces() * 4 > cfg.max_series_faces) break;
      base = subdivide_midpoint(base);
    }
  }

  const std::string markdown = render_markdown(info, meshes, series);
  const std::string svg = render_svg(info, series);
  if (!cfg.write) {
    std::cout << markdown;
    return 0;
  }
  const fs::path doc = cfg.root / cfg.doc, svg_path = cfg.root / cfg.svg;
  try {
    write_text(doc, replace_generated(read_text(doc), markdown));
    write_text(svg_path, svg);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr, "wrote %s and %s\n", (cfg.doc).string().c_str(), (cfg.svg).string().c_str());
  return 0;
}
