// smooth_turns: how many faces each smoothing method turns over or collapses, mesh by mesh.
//
//   smooth_turns [--iterations N] [--lambda L] [FILE or DIRECTORY ...]
//
// Without paths it reads every mesh in ../shared/meshes beside the repository, or data/ when that
// is absent. Each mesh is read in repair mode, triangulated (ear clipping) when it has polygons, and
// smoothed with the given options (default: the library's, 10 iterations, lambda 0.5, boundary
// fixed) by the uniform, cotangent and implicit methods. A face counts as turned when its normal
// after makes more than 90 degrees with its normal before, and as collapsed when its area was
// positive and is exactly zero after; faces of zero area before count in neither. Prints a Markdown
// table; exits with 1 if the cotangent or the implicit method turned or collapsed a face (they
// promise not to; the uniform column, unchecked as OpenMesh's umbrella smoother is, is for
// comparison).
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/smooth.h"
#include "hedge/core/build.h"
#include "hedge/core/export.h"
#include "hedge/io/io.h"

namespace fs = std::filesystem;

namespace {

struct Damage {
  std::size_t turned = 0, collapsed = 0;
};

Damage damage(const hedge::SurfaceMesh& before, const hedge::SurfaceMesh& after) {
  Damage d;
  for (hedge::Face f : before.faces()) {
    const hedge::Vec3d a = hedge::area_vector(before, f), b = hedge::area_vector(after, f);
    if (hedge::dot(a, a) == 0) continue;
    if (hedge::dot(b, b) == 0)
      ++d.collapsed;
    else if (hedge::dot(a, b) < 0)
      ++d.turned;
  }
  return d;
}

bool is_mesh_file(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl";
}

hedge::SurfaceMesh triangles_of(const hedge::SurfaceMesh& m) {
  bool polygons = false;
  for (hedge::Face f : m.faces()) polygons = polygons || m.valence(f) != 3;
  if (!polygons) return m;
  hedge::ExportOptions o;
  o.triangulation = hedge::Triangulation::ear;
  return hedge::build(hedge::to_indexed(m, o));
}

}  // namespace

int main(int argc, char** argv) {
  hedge::SmoothOptions base;
  std::vector<fs::path> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--iterations" && i + 1 < argc) {
      base.iterations = std::atoi(argv[++i]);
    } else if (a == "--lambda" && i + 1 < argc) {
      base.lambda = std::atof(argv[++i]);
    } else if (a == "-h" || a == "--help") {
      std::printf("usage: smooth_turns [--iterations N] [--lambda L] [FILE or DIRECTORY ...]\n");
      return 0;
    } else {
      inputs.emplace_back(a);
    }
  }
  if (inputs.empty()) {
    const fs::path root = HEDGE_BENCH_SOURCE_DIR;
    const fs::path shared = root.parent_path() / "shared" / "meshes";
    inputs.push_back(fs::is_directory(shared) ? shared : root / "data");
  }
  std::vector<fs::path> files;
  for (const fs::path& p : inputs) {
    if (fs::is_directory(p)) {
      for (const auto& e : fs::directory_iterator(p))
        if (is_mesh_file(e.path())) files.push_back(e.path());
    } else {
      files.push_back(p);
    }
  }
  std::sort(files.begin(), files.end());
  std::printf(
      "%d iterations, lambda %g, boundary fixed: faces turned by more than 90 degrees / collapsed to "
      "zero area\n\n",
      base.iterations, base.lambda);
  std::printf("| mesh | faces | uniform | cotangent | implicit |\n| --- | ---: | ---: | ---: | ---: |\n");
  bool clean = true;
  for (const fs::path& file : files) {
    std::string row = "| " + file.filename().string();
    try {
      const hedge::SurfaceMesh mesh = triangles_of(hedge::read_mesh(file.string()));
      row += " | " + std::to_string(mesh.n_faces());
      for (hedge::SmoothMethod method :
           {hedge::SmoothMethod::uniform, hedge::SmoothMethod::cotangent, hedge::SmoothMethod::implicit}) {
        hedge::SurfaceMesh m = mesh;
        hedge::SmoothOptions o = base;
        o.method = method;
        hedge::smooth(m, o);
        const Damage d = damage(mesh, m);
        if (method != hedge::SmoothMethod::uniform) clean = clean && d.turned == 0 && d.collapsed == 0;
        row += " | " + std::to_string(d.turned) + " / " + std::to_string(d.collapsed);
      }
    } catch (const std::exception& e) {
      row += std::string(" | error: ") + e.what() + " | | |";
    }
    std::printf("%s |\n", row.c_str());
    std::fflush(stdout);
  }
  return clean ? 0 : 1;
}
