// meshoptimizer backend: its simplifier on the flat arrays it works on (an index buffer over a
// position buffer). It has no mesh structure, so it takes part in the decimation only.
#include <meshoptimizer.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.h"

namespace bench {
namespace {

struct MOBox final : MeshBox {
  std::vector<float> xyz;
  std::vector<unsigned> indices;
  //! The simplifier's output and the per-vertex marks that count its vertices: sized before the
  //! timer starts (the output needs room for every input index, as the header says).
  std::vector<unsigned> simplified;
  std::size_t simplified_count = 0;
  std::vector<std::uint8_t> used;
  std::size_t n_vertices() const override { return xyz.size() / 3; }
  std::size_t n_faces() const override { return indices.size() / 3; }
};

std::unique_ptr<MeshBox> build(const Input& in) {
  auto box = std::make_unique<MOBox>();
  box->xyz = in.xyz;
  box->indices.assign(in.tri.begin(), in.tri.end());
  return box;
}

std::unique_ptr<MeshBox> prepare(const MeshBox& reference) {
  auto box = std::make_unique<MOBox>(static_cast<const MOBox&>(reference));
  box->simplified.assign(box->indices.size(), 0);
  box->used.assign(box->n_vertices(), 0);
  return box;
}

//! meshopt_simplify to a tenth of the indices, with no error limit (the largest target_error), then
//! the count of the vertices the result uses. Returns that count.
double decimate_op(Context& c) {
  MOBox& m = *static_cast<MOBox*>(c.mesh);
  const std::size_t target =
      static_cast<std::size_t>(static_cast<double>(m.indices.size() / 3) * decimate_ratio) * 3;
  m.simplified_count =
      meshopt_simplify(m.simplified.data(), m.indices.data(), m.indices.size(), m.xyz.data(), m.n_vertices(),
                       3 * sizeof(float), target, std::numeric_limits<float>::max(), 0, nullptr);
  std::size_t vertices = 0;
  for (std::size_t i = 0; i < m.simplified_count; ++i) {
    std::uint8_t& u = m.used[m.simplified[i]];
    vertices += u == 0;
    u = 1;
  }
  return static_cast<double>(vertices);
}

Input result(const MeshBox& edited) {
  const MOBox& m = static_cast<const MOBox&>(edited);
  Input out;
  std::vector<std::uint32_t> index(m.n_vertices(), UINT32_MAX);
  out.tri.reserve(m.simplified_count);
  for (std::size_t i = 0; i < m.simplified_count; ++i) {
    std::uint32_t& k = index[m.simplified[i]];
    if (k == UINT32_MAX) {
      k = static_cast<std::uint32_t>(out.n_vertices());
      for (int d = 0; d < 3; ++d) out.xyz.push_back(m.xyz[3 * m.simplified[i] + d]);
    }
    out.tri.push_back(k);
  }
  return out;
}

std::string check(const MeshBox&, const MeshBox& edited, double) {
  const MOBox& m = static_cast<const MOBox&>(edited);
  if (m.simplified_count % 3 != 0) return "an index count that is not a multiple of 3; ";
  for (std::size_t i = 0; i < m.simplified_count; ++i)
    if (m.simplified[i] >= m.n_vertices()) return "an index out of range; ";
  return "";
}

}  // namespace

Backend meshopt_backend() {
  Backend b;
  b.label = "meshopt";
  b.key = "meshopt";
  b.notes = "meshoptimizer " + std::to_string(MESHOPTIMIZER_VERSION / 1000) + "." +
            std::to_string(MESHOPTIMIZER_VERSION % 1000 / 10) +
            ": meshopt_simplify on the index and position arrays (decimation only; options 0)";
  b.build = build;
  b.ops["decimate"] = {prepare, decimate_op, check, result};
  b.mesh_structure = false;
  return b;
}

}  // namespace bench
