// NativeMesh::fracture_solid and solid_fracture_check (the JS API's Mesh.fractureSolid,
// Mesh.solidFractureRefusal and Mesh.solidFractureRefusalCode, see wasm_mesh.h), through the mesh's
// picking tree.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "binding/names.h"
#include "hedge/algorithms/fracture_solid.h"
#include "hedge/core/export.h"
#include "hedge/error.h"
#include "wasm_mesh.h"

namespace hedge::wasm {

namespace {

//! Numbers per piece in the packed result of WasmMesh::fracture_solid.
constexpr std::size_t kPieceScalars = 6 + 6 * 3 + 9;

//! The options of a solid fracture from the JS layer's typed object; fracture_solid() and
//! solid_fracture_refusal() check the values, naming the field.
SolidFractureOptions solid_options(const char* call, const std::string& preset, const val& custom,
                                   const val& js) {
  SolidFractureOptions o;
  o.material = preset.empty() ? material_from_js(custom) : fracture_material(preset);
  const double seed = js["seed"].as<double>();
  if (!(seed >= 0 && seed <= 9007199254740992.0 && std::floor(seed) == seed))
    throw InvalidInputError(std::string(call) + ": the seed must be a whole number in [0, 2^53]");
  o.seed = std::uint64_t(seed);
  o.radius = js["radius"].as<double>();
  o.radius_fraction = js["radiusFraction"].as<double>();
  const double inner = js["innerSubmesh"].as<double>();
  if (!(inner >= -1 && inner <= 2147483647.0 && std::floor(inner) == inner))
    throw InvalidInputError(std::string(call) + ": innerSubmesh must be -1 or a whole number >= 0");
  o.inner_submesh = std::int32_t(inner);
  o.density = js["density"].as<double>();
  o.tolerance = js["tolerance"].as<double>();
  o.hulls = js["hulls"].as<bool>();
  return o;
}

//! The pieces packed into a few typed arrays (the JS layer makes the piece objects): a val call
//! per field would cost more than the strike itself.
val pack_pieces(std::vector<SolidPiece>& pieces) {
  const std::size_t n = pieces.size();
  std::vector<double> scalars;
  scalars.reserve(n * kPieceScalars);
  std::vector<float> hull_positions;
  std::vector<std::uint32_t> hull_indices, hull_vertex_offsets{0}, hull_index_offsets{0};
  val meshes = val::array();
  for (std::size_t i = 0; i < n; ++i) {
    SolidPiece& piece = pieces[i];
    const MassProperties& mp = piece.mass;
    const double head[] = {double(piece.mesh.n_faces()),      piece.volume,        piece.cap_area, mp.mass,
                           double(int(piece.hull.dimension)), piece.hull.tolerance};
    scalars.insert(scalars.end(), std::begin(head), std::end(head));
    for (const Vec3d& v : {piece.centroid, mp.centre_of_mass, mp.principal_moments, mp.principal_axes[0],
                           mp.principal_axes[1], mp.principal_axes[2]})
      scalars.insert(scalars.end(), {v.x, v.y, v.z});
    scalars.insert(scalars.end(), mp.inertia.begin(), mp.inertia.end());
    const IndexedMesh h = to_indexed(piece.hull.mesh);
    for (const Vec3& p : h.positions) hull_positions.insert(hull_positions.end(), {p.x, p.y, p.z});
    hull_indices.insert(hull_indices.end(), h.indices.begin(), h.indices.end());
    hull_vertex_offsets.push_back(std::uint32_t(hull_positions.size() / 3));
    hull_index_offsets.push_back(std::uint32_t(hull_indices.size()));
    auto state = std::make_shared<MeshState>();
    state->mesh = std::move(piece.mesh);
    meshes.set(i, WasmMesh(std::move(state)));
  }
  val out = val::object();
  out.set("count", double(n));
  out.set("scalars", js_doubles(scalars.data(), scalars.size()));
  out.set("meshes", meshes);
  out.set("hullPositions", js_floats(hull_positions.data(), hull_positions.size()));
  out.set("hullIndices", js_uints(hull_indices.data(), hull_indices.size()));
  out.set("hullVertexOffsets", js_uints(hull_vertex_offsets.data(), hull_vertex_offsets.size()));
  out.set("hullIndexOffsets", js_uints(hull_index_offsets.data(), hull_index_offsets.size()));
  return out;
}

}  // namespace

val WasmMesh::fracture_solid(val impact, const std::string& preset, val custom, val options) {
  return guarded([&] {
    const Vec3 at = point_from_js(impact, "fractureSolid: the impact");
    const SolidFractureOptions o = solid_options("fractureSolid", preset, custom, options);
    FaceBvh& bvh = binding::picking_tree(*s_);
    const auto start = std::chrono::steady_clock::now();
    SolidFractureResult r = hedge::fracture_solid(s_->mesh, at, o, &bvh);
    const auto fractured = std::chrono::steady_clock::now();

    std::vector<double> bonds;
    bonds.reserve(r.bonds.size() * 3);
    for (const SolidBond& b : r.bonds)
      bonds.insert(bonds.end(), {double(b.a), b.b == kSolidRemaining ? -1.0 : double(b.b), b.area});
    val result = val::object();
    result.set("pieces", pack_pieces(r.pieces));
    result.set("bonds", js_doubles(bonds.data(), bonds.size()));
    result.set("impactFace", js_index(r.impact_face.idx()));
    result.set("impactPoint", js_vec3(r.impact_point));
    result.set("radius", r.radius);
    val seconds = val::object();
    seconds.set("locate", r.seconds.locate);
    seconds.set("cells", r.seconds.cells);
    seconds.set("clip", r.seconds.clip);
    seconds.set("cap", r.seconds.cap);
    seconds.set("assemble", r.seconds.assemble);
    seconds.set("perPiece", r.seconds.per_piece);
    seconds.set("fracture", std::chrono::duration<double>(fractured - start).count());
    seconds.set("pack", std::chrono::duration<double>(std::chrono::steady_clock::now() - fractured).count());
    result.set("seconds", seconds);
    return result;
  });
}

val WasmMesh::solid_fracture_check(val impact, const std::string& preset, val custom, val options) {
  return guarded([&] {
    const Vec3 at = point_from_js(impact, "solidFractureRefusal: the impact");
    const SolidFractureOptions o = solid_options("solidFractureRefusal", preset, custom, options);
    const SolidFractureCheck why = hedge::solid_fracture_check(s_->mesh, at, o, &binding::picking_tree(*s_));
    val out = val::object();
    out.set("code", std::string(binding::name(why.code)));
    out.set("message", why.message);
    return out;
  });
}

}  // namespace hedge::wasm
