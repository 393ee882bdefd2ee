// The C ABI: solid fracture (hedge/algorithms/fracture_solid.h). A strike's pieces and bonds go
// into a result object (a hedge_solid_fracture handle), since how many bonds a strike makes is
// known only once it is done; each piece's mesh and hull are mesh handles of their own, as
// hedge_mesh_fracture()'s shards are.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "binding/names.h"
#include "capi_internal.h"
#include "hedge/algorithms/fracture_solid.h"

using namespace hedge;
using namespace hedge::capi;

namespace {

// The C ABI's refusal codes are SolidRefusal's positions (binding::constant()).
static_assert(HEDGE_SOLID_REFUSAL_OPEN == static_cast<int>(SolidRefusal::open) &&
                  HEDGE_SOLID_REFUSAL_NON_MANIFOLD == static_cast<int>(SolidRefusal::non_manifold) &&
                  HEDGE_SOLID_REFUSAL_BAD_OPTION == static_cast<int>(SolidRefusal::bad_option) &&
                  HEDGE_SOLID_REFUSAL_BAD_IMPACT == static_cast<int>(SolidRefusal::bad_impact) &&
                  HEDGE_SOLID_REFUSAL_OFF_SURFACE == static_cast<int>(SolidRefusal::off_surface) &&
                  HEDGE_SOLID_REFUSAL_NO_FACE == static_cast<int>(SolidRefusal::no_face) &&
                  HEDGE_SOLID_REFUSAL_BAD_RADIUS == static_cast<int>(SolidRefusal::bad_radius) &&
                  HEDGE_SOLID_REFUSAL_COUNT == static_cast<int>(SolidRefusal::foreign_tree) + 1,
              "c_api.h's HEDGE_SOLID_REFUSAL_* and SolidRefusal differ");

SolidFractureOptions to_solid_options(const hedge_solid_fracture_options& o) {
  if (o.ring_count > HEDGE_FRACTURE_MAX_RINGS)
    fail(HEDGE_ERROR_INVALID_ARGUMENT, "ring_count must be at most HEDGE_FRACTURE_MAX_RINGS (" +
                                           std::to_string(HEDGE_FRACTURE_MAX_RINGS) + "), got " +
                                           std::to_string(o.ring_count));
  SolidFractureOptions s;
  s.material.name = "custom";
  s.material.rings.clear();
  for (std::uint32_t i = 0; i < o.ring_count; ++i)
    s.material.rings.push_back({o.rings[i].points, o.rings[i].spacing, o.rings[i].jitter});
  s.radius = o.radius;
  s.radius_fraction = o.radius_fraction;
  s.seed = o.seed;
  s.density = o.density;
  s.tolerance = o.tolerance;
  s.hulls = need_bool(o.hulls, "hulls");
  s.inner_submesh = o.inner_submesh;
  return s;
}

hedge_solid_fracture_options options_or_stone(const hedge_solid_fracture_options* options) {
  return options_or_defaults(options, [](hedge_solid_fracture_options* out) {
    return hedge_solid_fracture_options_default(HEDGE_FRACTURE_STONE, out);
  });
}

void fill_piece(const SolidPiece& p, hedge_solid_piece& out) {
  out = hedge_solid_piece{};
  out.volume = p.volume;
  out.cap_area = p.cap_area;
  out.mass = p.mass.mass;
  const Vec3d& c = p.mass.centre_of_mass;
  out.centre_of_mass[0] = c.x, out.centre_of_mass[1] = c.y, out.centre_of_mass[2] = c.z;
  std::copy(p.mass.inertia.begin(), p.mass.inertia.end(), out.inertia);
  const Vec3d& m = p.mass.principal_moments;
  out.principal_moments[0] = m.x, out.principal_moments[1] = m.y, out.principal_moments[2] = m.z;
  for (int a = 0; a < 3; ++a) {
    const Vec3d& axis = p.mass.principal_axes[a];
    out.principal_axes[3 * a] = axis.x, out.principal_axes[3 * a + 1] = axis.y;
    out.principal_axes[3 * a + 2] = axis.z;
  }
  out.hull_dimension = static_cast<std::int32_t>(p.hull.dimension);
}

std::uint32_t bond_end(std::size_t i) {
  return i == kSolidRemaining ? HEDGE_SOLID_REMAINING : static_cast<std::uint32_t>(i);
}

}  // namespace

extern "C" {

hedge_status hedge_solid_fracture_options_default(int32_t preset, hedge_solid_fracture_options* out_options) {
  return guard([&] {
    hedge_solid_fracture_options& o = need(out_options, "out_options");
    static const char* const names[] = {"glass", "stone", "wood", "ice"};
    if (preset < HEDGE_FRACTURE_GLASS || preset > HEDGE_FRACTURE_ICE)
      fail(HEDGE_ERROR_INVALID_ARGUMENT,
           "preset must be HEDGE_FRACTURE_GLASS, _STONE, _WOOD or _ICE, got " + std::to_string(preset));
    const FractureMaterial m = fracture_material(names[preset]);
    const SolidFractureOptions d;
    o = hedge_solid_fracture_options{};
    o.ring_count = static_cast<std::uint32_t>(m.rings.size());
    for (std::size_t i = 0; i < m.rings.size(); ++i)
      o.rings[i] = {m.rings[i].spacing, m.rings[i].jitter, m.rings[i].points, 0};
    o.hulls = d.hulls ? 1 : 0;
    o.radius = d.radius;
    o.radius_fraction = d.radius_fraction;
    o.seed = d.seed;
    o.density = d.density;
    o.tolerance = d.tolerance;
    o.inner_submesh = d.inner_submesh;
  });
}

hedge_status hedge_solid_fracture_refusal(hedge_mesh* mesh, float x, float y, float z,
                                          const hedge_solid_fracture_options* options, char* buffer,
                                          uint32_t capacity, uint32_t* out_size) {
  return guard([&] {
    auto object = find_mesh(mesh);
    need(out_size, "out_size");
    const hedge_solid_fracture_options o = options_or_stone(options);
    std::string why;
    const Vec3 impact{x, y, z};
    try {
      const SolidFractureOptions s = to_solid_options(o);
      why = solid_fracture_refusal(object->mesh, impact, s, &picking_tree(*object));
    } catch (const binding::BindingError& e) {
      why = e.message;  // an option out of range is a reason too
    }
    copy_string(why, buffer, capacity, out_size);
  });
}

hedge_status hedge_solid_fracture_refusal_code(hedge_mesh* mesh, float x, float y, float z,
                                               const hedge_solid_fracture_options* options,
                                               hedge_solid_refusal* out_code) {
  return guard([&] {
    auto object = find_mesh(mesh);
    hedge_solid_refusal& code = need(out_code, "out_code");
    const hedge_solid_fracture_options o = options_or_stone(options);
    SolidRefusal why = SolidRefusal::bad_option;  // an option out of range is a reason too
    try {
      const SolidFractureOptions s = to_solid_options(o);
      why = solid_fracture_check(object->mesh, {x, y, z}, s, &picking_tree(*object)).code;
    } catch (const binding::BindingError&) {
    }
    code = binding::constant(why);
  });
}

hedge_status hedge_mesh_fracture_solid(hedge_mesh* mesh, float x, float y, float z,
                                       const hedge_solid_fracture_options* options,
                                       hedge_solid_fracture** out_result) {
  return guard([&] {
    hedge_solid_fracture*& result = need(out_result, "out_result");
    result = nullptr;
    auto object = find_mesh(mesh);
    const SolidFractureOptions s = to_solid_options(options_or_stone(options));
    const Vec3 impact = need_point(x, y, z, "solid fracture impact");
    // Its InvalidInputError becomes HEDGE_ERROR_INVALID_ARGUMENT, the mesh unchanged. The region is
    // found through the mesh's picking tree, which fracture_solid() keeps up to date.
    SolidFractureResult r = fracture_solid(object->mesh, impact, s, &picking_tree(*object));
    auto out = std::make_shared<SolidFractureObject>();
    out->summary.piece_count = to_u32(r.pieces.size(), "pieces");
    out->summary.bond_count = to_u32(r.bonds.size(), "bonds");
    out->summary.impact_face = r.impact_face.idx();
    out->summary.impact_point[0] = r.impact_point.x;
    out->summary.impact_point[1] = r.impact_point.y;
    out->summary.impact_point[2] = r.impact_point.z;
    out->summary.radius = r.radius;
    out->pieces.resize(r.pieces.size());
    out->bonds.reserve(r.bonds.size());
    for (const SolidBond& b : r.bonds) out->bonds.push_back({bond_end(b.a), bond_end(b.b), b.area});
    // Every object is made before any handle is registered, so a failure leaves none behind.
    std::vector<std::shared_ptr<MeshObject>> meshes, hulls;
    for (SolidPiece& p : r.pieces) {
      fill_piece(p, out->pieces[meshes.size()]);
      meshes.push_back(std::make_shared<MeshObject>());
      meshes.back()->mesh = std::move(p.mesh);
      hulls.push_back(nullptr);
      if (p.hull.mesh.n_faces() > 0) {
        hulls.back() = std::make_shared<MeshObject>();
        hulls.back()->mesh = std::move(p.hull.mesh);
      }
    }
    for (std::size_t i = 0; i < meshes.size(); ++i) {
      out->pieces[i].mesh = register_mesh(std::move(meshes[i]));
      out->pieces[i].hull = hulls[i] ? register_mesh(std::move(hulls[i])) : nullptr;
    }
    result = register_solid_fracture(std::move(out));
  });
}

hedge_status hedge_solid_fracture_get_summary(const hedge_solid_fracture* result,
                                              hedge_solid_fracture_summary* out_summary) {
  return guard([&] {
    auto r = find_solid_fracture(result);
    need(out_summary, "out_summary") = r->summary;
  });
}

hedge_status hedge_solid_fracture_copy_pieces(const hedge_solid_fracture* result, hedge_solid_piece* buffer,
                                              uint32_t capacity, uint32_t* out_count) {
  return guard([&] {
    auto r = find_solid_fracture(result);
    copy_out(std::span<const hedge_solid_piece>(r->pieces), buffer, capacity, out_count);
  });
}

hedge_status hedge_solid_fracture_copy_bonds(const hedge_solid_fracture* result, hedge_solid_bond* buffer,
                                             uint32_t capacity, uint32_t* out_count) {
  return guard([&] {
    auto r = find_solid_fracture(result);
    copy_out(std::span<const hedge_solid_bond>(r->bonds), buffer, capacity, out_count);
  });
}

hedge_status hedge_solid_fracture_destroy(hedge_solid_fracture* result) {
  return guard([&] {
    // Freed outside the registry's lock.
    std::shared_ptr<const SolidFractureObject> object = unregister_solid_fracture(result);
    object.reset();
  });
}

}  // extern "C"
