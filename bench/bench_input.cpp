// Inputs of the benchmarks: files read through hedge's io, midpoint subdivision, default mesh list.
#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bench_common.h"
#include "hedge/io/io.h"

namespace bench {

namespace fs = std::filesystem;

Input load_input(const std::string& path) {
  hedge::IndexedMesh m = hedge::read_indexed_file(path);
  if (!m.is_triangles()) {
    bool all_tri =
        std::all_of(m.face_sizes.begin(), m.face_sizes.end(), [](std::uint32_t s) { return s == 3; });
    if (!all_tri) throw std::runtime_error(path + ": not a triangle mesh");
  }
  Input in;
  in.name = fs::path(path).filename().string();
  in.xyz.resize(3 * m.positions.size());
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    in.xyz[3 * i] = m.positions[i].x;
    in.xyz[3 * i + 1] = m.positions[i].y;
    in.xyz[3 * i + 2] = m.positions[i].z;
  }
  in.tri = std::move(m.indices);
  return in;
}

Input subdivide(const Input& in) {
  const std::size_t nv = in.n_vertices(), nf = in.n_faces();
  // One entry per face corner c, standing for the edge from corner c to corner c+1 of its face;
  // sorting by the unordered vertex pair puts the two sides of an edge next to each other.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(3 * nf);
  for (std::size_t f = 0; f < nf; ++f)
    for (std::size_t k = 0; k < 3; ++k) {
      std::uint64_t a = in.tri[3 * f + k], b = in.tri[3 * f + (k + 1) % 3];
      if (a > b) std::swap(a, b);
      keys[3 * f + k] = {(a << 32) | b, static_cast<std::uint32_t>(3 * f + k)};
    }
  std::sort(keys.begin(), keys.end());

  Input out;
  out.name = in.name;
  out.xyz = in.xyz;
  std::vector<std::uint32_t> mid(3 * nf);
  std::uint32_t next = static_cast<std::uint32_t>(nv);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (i == 0 || keys[i].first != keys[i - 1].first) {
      auto a = static_cast<std::uint32_t>(keys[i].first >> 32), b = static_cast<std::uint32_t>(keys[i].first);
      for (int d = 0; d < 3; ++d) out.xyz.push_back(0.5f * (in.xyz[3 * a + d] + in.xyz[3 * b + d]));
      ++next;
    }
    mid[keys[i].second] = next - 1;
  }
  out.tri.reserve(12 * nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const std::uint32_t a = in.tri[3 * f], b = in.tri[3 * f + 1], c = in.tri[3 * f + 2];
    const std::uint32_t ab = mid[3 * f], bc = mid[3 * f + 1], ca = mid[3 * f + 2];
    for (std::uint32_t t : {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca}) out.tri.push_back(t);
  }
  return out;
}

bool is_closed(const Input& in) {
  // Directed edges sorted by (vertex pair, direction): each pair must occur exactly twice, once
  // per direction.
  std::vector<std::pair<std::uint64_t, std::uint8_t>> keys(in.tri.size());
  for (std::size_t f = 0; f < in.n_faces(); ++f)
    for (std::size_t k = 0; k < 3; ++k) {
      std::uint64_t a = in.tri[3 * f + k], b = in.tri[3 * f + (k + 1) % 3];
      keys[3 * f + k] =
          a < b ? std::pair{a << 32 | b, std::uint8_t{0}} : std::pair{b << 32 | a, std::uint8_t{1}};
    }
  if (keys.size() % 2) return false;
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 0; i < keys.size(); i += 2)
    if (keys[i].first != keys[i + 1].first || keys[i].second != 0 || keys[i + 1].second != 1 ||
        (i + 2 < keys.size() && keys[i + 2].first == keys[i].first))
      return false;
  return true;
}

Input load_spec(const std::string& spec) {
  std::string path = spec;
  int rounds = 0;
  auto colon = spec.rfind(":sub");
  if (colon != std::string::npos && colon + 4 < spec.size() &&
      spec.find_first_not_of("0123456789", colon + 4) == std::string::npos) {
    path = spec.substr(0, colon);
    rounds = std::stoi(spec.substr(colon + 4));
  }
  Input in = load_input(path);
  for (int r = 0; r < rounds; ++r) in = subdivide(in);
  if (rounds > 0) in.name += " x" + std::to_string(1 << (2 * rounds)) + " (subdivided)";
  in.closed = is_closed(in);
  return in;
}

std::string find_root(const std::string& hint) {
  if (!hint.empty()) return hint;
  std::error_code ec;
  for (fs::path p = fs::current_path(ec); !ec && !p.empty(); p = p.parent_path()) {
    if (fs::exists(p / "include" / "hedge", ec)) return p.string();
    if (p == p.parent_path()) break;
  }
#ifdef HEDGE_BENCH_SOURCE_DIR
  return HEDGE_BENCH_SOURCE_DIR;
#else
  return ".";
#endif
}

std::vector<std::string> default_mesh_specs(const std::string& root, std::string& note) {
  std::error_code ec;
  const fs::path shared = fs::path(root) / ".." / "shared" / "meshes";
  if (fs::exists(shared / "armadillo.obj", ec)) {
    note = "meshes from ../shared/meshes";
    std::vector<std::string> specs;
    const std::string arm = (shared / "armadillo.obj").lexically_normal().string();
    specs.push_back(arm);
    if (fs::exists(shared / "igea.ply", ec))
      specs.push_back((shared / "igea.ply").lexically_normal().string());
    specs.push_back(arm + ":sub2");
    return specs;
  }
  const fs::path data = fs::path(root) / "data";
  std::vector<std::string> specs;  // STL is left out: it stores an unwelded triangle soup
  if (fs::is_directory(data, ec))
    for (const auto& e : fs::directory_iterator(data, ec)) {
      std::string ext = e.path().extension().string();
      std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
      if (e.is_regular_file() && (ext == ".obj" || ext == ".off" || ext == ".ply"))
        specs.push_back(e.path().string());
    }
  std::sort(specs.begin(), specs.end());
  note = specs.empty() ? "../shared/meshes is absent and data/ holds no mesh"
                       : "../shared/meshes is absent: falling back to the repository's data/ meshes";
  return specs;
}

}  // namespace bench
