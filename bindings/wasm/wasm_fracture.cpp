// NativeMesh::fracture (the JS API's Mesh.fracture, see wasm_mesh.h), through the mesh's picking
// tree.
#include <chrono>
#include <cmath>
#include <iterator>

#include "hedge/algorithms/fracture.h"
#include "hedge/core/export.h"
#include "hedge/error.h"
#include "wasm_mesh.h"

namespace hedge::wasm {

namespace {

//! FractureUnits by name ("diagonal_fraction", "model", "edge_lengths").
FractureUnits units_from_js(const std::string& name) {
  for (FractureUnits u :
       {FractureUnits::diagonal_fraction, FractureUnits::model, FractureUnits::edge_lengths})
    if (name == fracture_units_name(u)) return u;
  throw InvalidInputError("fracture: units must be 'diagonal_fraction', 'model' or 'edge_lengths', got '" +
                          name + "'");
}

}  // namespace

//! A fracture material from the object the JS layer made of a custom material (see
//! WasmMesh::fracture); fracture() checks the values.
FractureMaterial material_from_js(const val& m) {
  FractureMaterial out;
  out.name = m["name"].as<std::string>();
  std::vector<double> rings;
  copy_from_js(m["rings"], rings, js_length(m["rings"], "material.rings"));
  if (rings.size() % 3 != 0) throw InvalidInputError("material.rings: expected 3 numbers per ring");
  for (std::size_t i = 0; i < rings.size(); i += 3) {
    const double points = rings[i];
    if (!(points >= 0 && points <= 100000 && std::floor(points) == points))
      throw InvalidInputError("material '" + out.name + "' rings[" + std::to_string(i / 3) +
                              "].points must be a whole number in [0, 100000]");
    out.rings.push_back(FractureRing{unsigned(points), rings[i + 1], rings[i + 2]});
  }
  const val grain = m["grain"];
  out.grain = Vec3{float(grain[0].as<double>()), float(grain[1].as<double>()), float(grain[2].as<double>())};
  out.grain_stretch = m["grainStretch"].as<double>();
  out.refine_edge = m["refineEdge"].as<double>();
  out.units = units_from_js(m["units"].as<std::string>());
  out.radius = m["radius"].as<double>();
  return out;
}

namespace {

//! Numbers per shard in the packed result of WasmMesh::fracture.
constexpr std::size_t kShardScalars = 7 + 6 * 3 + 9 + 1;

}  // namespace

val WasmMesh::fracture(val impact, const std::string& preset, val custom, double seed, double break_radius,
                       const std::string& units, double radius, double thickness, double density,
                       double shell_thickness, double tolerance, bool hulls) {
  return guarded([&] {
    const Vec3 at = point_from_js(impact, "fracture: the impact");
    if (!(seed >= 0 && seed <= 9007199254740992.0 && std::floor(seed) == seed))
      throw InvalidInputError("fracture: the seed must be a whole number in [0, 2^53]");
    FractureOptions options;
    options.material = preset.empty() ? material_from_js(custom) : fracture_material(preset);
    // "" and 0: the material's own; anything else is checked by fracture() (finite, positive).
    if (!units.empty()) options.material.units = units_from_js(units);
    if (radius != 0) options.material.radius = radius;
    // 0: as above; anything else is checked (finite, positive) by the scaling.
    if (break_radius != 0) options.material = fracture_material_at_radius(options.material, break_radius);
    options.shell_thickness = shell_thickness;
    options.seed = std::uint64_t(seed);
    options.thickness = thickness;
    options.density = density;
    options.tolerance = tolerance;
    options.hulls = hulls;
    FaceBvh& bvh = binding::picking_tree(*s_);
    const auto start = std::chrono::steady_clock::now();
    FractureResult r = hedge::fracture(s_->mesh, at, options, &bvh);
    const auto fractured = std::chrono::steady_clock::now();

    // Packed into a few typed arrays (the JS layer makes the shard objects): a val call per field
    // would cost more than the fracture itself.
    const std::size_t n = r.shards.size();
    std::vector<double> scalars;
    scalars.reserve(n * kShardScalars);
    std::vector<float> hull_positions;
    std::vector<std::uint32_t> hull_indices, hull_vertex_offsets{0}, hull_index_offsets{0};
    val meshes = val::array();
    for (std::size_t i = 0; i < n; ++i) {
      Shard& shard = r.shards[i];
      const MassProperties& mp = shard.mass;
      const double head[] = {double(shard.mesh.n_faces()), shard.area, shard.mass.volume,
                             shard.closed ? 1.0 : 0.0,     mp.mass,    double(int(shard.hull.dimension)),
                             shard.hull.tolerance};
      scalars.insert(scalars.end(), std::begin(head), std::end(head));
      for (const Vec3d& v : {shard.centroid, mp.centre_of_mass, mp.principal_moments, mp.principal_axes[0],
                             mp.principal_axes[1], mp.principal_axes[2]})
        scalars.insert(scalars.end(), {v.x, v.y, v.z});
      scalars.insert(scalars.end(), mp.inertia.begin(), mp.inertia.end());
      scalars.push_back(shard.shell_thickness);
      const IndexedMesh h = to_indexed(shard.hull.mesh);
      for (const Vec3& p : h.positions) hull_positions.insert(hull_positions.end(), {p.x, p.y, p.z});
      hull_indices.insert(hull_indices.end(), h.indices.begin(), h.indices.end());
      hull_vertex_offsets.push_back(std::uint32_t(hull_positions.size() / 3));
      hull_index_offsets.push_back(std::uint32_t(hull_indices.size()));
      auto state = std::make_shared<MeshState>();
      state->mesh = std::move(shard.mesh);
      meshes.set(i, WasmMesh(std::move(state)));
    }
    val shards = val::object();
    shards.set("count", double(n));
    shards.set("scalars", js_doubles(scalars.data(), scalars.size()));
    shards.set("meshes", meshes);
    shards.set("hullPositions", js_floats(hull_positions.data(), hull_positions.size()));
    shards.set("hullIndices", js_uints(hull_indices.data(), hull_indices.size()));
    shards.set("hullVertexOffsets", js_uints(hull_vertex_offsets.data(), hull_vertex_offsets.size()));
    shards.set("hullIndexOffsets", js_uints(hull_index_offsets.data(), hull_index_offsets.size()));
    val seconds = val::object();
    seconds.set("locate", r.seconds.locate);
    seconds.set("scatter", r.seconds.scatter);
    seconds.set("cut", r.seconds.cut);
    seconds.set("detach", r.seconds.detach);
    seconds.set("hulls", r.seconds.hulls);
    seconds.set("fracture", std::chrono::duration<double>(fractured - start).count());
    seconds.set("pack", std::chrono::duration<double>(std::chrono::steady_clock::now() - fractured).count());
    val result = val::object();
    result.set("shards", shards);
    result.set("impactFace", js_index(r.impact_face.idx()));
    result.set("impactPoint", js_vec3(r.impact_point));
    result.set("breakRadius", r.break_radius);
    result.set("seconds", seconds);
    return result;
  });
}

}  // namespace hedge::wasm
