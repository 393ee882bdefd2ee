// Solid fracture. See include/hedge/algorithms/fracture_solid.h for the contract.
#include "hedge/algorithms/fracture_solid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "format.h"
#include "fracture_solid_internal.h"
#include "fracture_solid_strike.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/core/build.h"
#include "hedge/core/triangulate.h"
#include "hedge/error.h"

namespace hedge {

using detail::number;
using namespace solid_detail;

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point& t) {
  const Clock::time_point now = Clock::now();
  const double s = std::chrono::duration<double>(now - t).count();
  t = now;
  return s;
}

constexpr int kAttempts = 6;
constexpr double kNudge = 1e-5;

//! The options' error, or empty.
std::string check_options(const SolidFractureOptions& o) {
  try {
    FractureOptions f;
    f.material = o.material;
    fracture_break_points(f);
  } catch (const InvalidInputError& e) {
    std::string what = e.what();
    const std::string prefix = "fracture: ";
    if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
    return what;
  }
  if (o.material.rings.empty()) return "material '" + o.material.name + "' has no rings";
  if (!std::isfinite(o.radius) || o.radius < 0)
    return "radius must be finite and >= 0, is " + number(o.radius);
  if (!std::isfinite(o.radius_fraction) || o.radius_fraction <= 0 || o.radius_fraction > 10)
    return "radius_fraction must be in (0, 10], is " + number(o.radius_fraction);
  if (o.inner_submesh < -1)
    return "inner_submesh must be -1 (automatic) or >= 0, is " + std::to_string(o.inner_submesh);
  if (!std::isfinite(o.density) || o.density <= 0)
    return "density must be finite and positive, is " + number(o.density);
  if (!std::isfinite(o.tolerance) || o.tolerance < 0)
    return "tolerance must be finite and >= 0, is " + number(o.tolerance);
  return {};
}

//! The strike's setting: the tree, the located impact and the radii; or the reason it cannot be.
struct Setup {
  std::optional<FaceBvh> own;
  FaceBvh* tree = nullptr;
  LocateResult hit;
  double radius = 0;         // the outer ring's
  double region_radius = 0;  // P's inscribed sphere
  FractureMaterial material;
  std::string refusal;
  SolidRefusal code = SolidRefusal::none;

  //! Refuses the strike: returns false, to be returned by setup().
  bool refuse(SolidRefusal c, std::string why) {
    code = c;
    refusal = std::move(why);
    return false;
  }
};

std::string point_text(const Vec3& p) {
  return "(" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + ")";
}

//! Fills `s`; false (s.code and s.refusal say why) if the strike cannot be made.
bool setup(SurfaceMesh& mesh, const Vec3& impact, const SolidFractureOptions& o, FaceBvh* bvh, Setup& s) {
  if (std::string e = check_options(o); !e.empty()) return s.refuse(SolidRefusal::bad_option, e);
  if (!is_finite(impact))
    return s.refuse(SolidRefusal::bad_impact, "the impact " + point_text(impact) + " is not finite");
  if (mesh.n_faces() == 0) return s.refuse(SolidRefusal::no_face, "the mesh has no face");
  if (bvh && bvh->mesh() != &mesh)
    return s.refuse(SolidRefusal::foreign_tree, "the FaceBvh was built over another mesh");
  if (bvh) {
    bvh->update();
    s.tree = bvh;
  } else {
    s.own.emplace(mesh);
    s.tree = &*s.own;
  }
  const std::optional<LocateResult> hit = s.tree->closest_point(impact);
  if (!hit) return s.refuse(SolidRefusal::off_surface, "no face found near the impact");
  s.hit = *hit;
  const double tolerance = o.tolerance > 0 ? o.tolerance : 1e-3 * longest_edge(mesh, hit->face);
  const double distance = std::sqrt(hit->squared_distance);
  if (!(distance <= tolerance))
    return s.refuse(SolidRefusal::off_surface,
                    "the impact " + point_text(impact) + " is " + number(distance) +
                        " from the nearest face (" + std::to_string(hit->face.idx()) +
                        "), beyond the tolerance " + number(tolerance) +
                        "; the nearest point of the surface is " + point_text(hit->point));
  double radius = o.radius;
  if (radius == 0) {
    Vec3 lo, hi;
    s.tree->bounds(lo, hi);
    radius = o.radius_fraction * norm(to_double(hi) - to_double(lo));
  }
  if (!(radius > 0) || !std::isfinite(radius))
    return s.refuse(SolidRefusal::bad_radius,
                    "the break radius is " + number(radius) + ", not positive (a mesh of zero size?)");
  s.radius = radius;
  s.material = fracture_material_at_radius(o.material, radius);
  s.region_radius = radius + 0.5 * s.material.rings.back().spacing;
  // Only a closed mesh encloses a solid, and a hole away from the region cannot be seen from it: a
  // pass over the half-edges, kept by the tree until the mesh changes (a strike keeps it closed).
  Halfedge open;
  if (!s.tree->mesh_closed(&open))
    return s.refuse(SolidRefusal::open,
                    "the mesh is open: edge " + std::to_string(SurfaceMesh::edge(open).idx()) +
                        " (vertices " + std::to_string(mesh.from_vertex(open).idx()) + " and " +
                        std::to_string(mesh.to_vertex(open).idx()) +
                        ") has a face on one side only, and only a closed mesh encloses a solid");
  return true;
}

//! Why the faces about the region cannot be broken as a solid: a boundary edge or a non-manifold
//! vertex among them, or none. O(region).
SolidFractureCheck check_closed(const SurfaceMesh& mesh, const std::vector<Face>& faces) {
  for (Face f : faces)
    for (Halfedge h : mesh.halfedges(f)) {
      if (mesh.is_boundary(SurfaceMesh::twin(h)))
        return {SolidRefusal::open,
                "the mesh is open near the impact: edge " + std::to_string(SurfaceMesh::edge(h).idx()) +
                    " (vertices " + std::to_string(mesh.from_vertex(h).idx()) + " and " +
                    std::to_string(mesh.to_vertex(h).idx()) + ") has a face on one side only"};
      if (!mesh.is_manifold(mesh.to_vertex(h)))
        return {SolidRefusal::non_manifold, "the mesh is not manifold near the impact: vertex " +
                                                std::to_string(mesh.to_vertex(h).idx()) +
                                                " joins several fans of faces"};
    }
  return {};
}

}  // namespace

bool solid_refusal_falls_back(SolidRefusal code) noexcept {
  return code == SolidRefusal::open || code == SolidRefusal::non_manifold;
}

SolidFractureCheck solid_fracture_check(SurfaceMesh& mesh, const Vec3& impact,
                                        const SolidFractureOptions& options, FaceBvh* bvh) {
  Setup s;
  try {
    if (!setup(mesh, impact, options, bvh, s)) return {s.code, s.refusal};
  } catch (const InvalidInputError& e) {
    return {SolidRefusal::bad_option, e.what()};
  }
  std::vector<Face> faces;
  const StrikeInput in{mesh, *s.tree, to_double(s.hit.point), s.region_radius, s.material, options};
  region_faces(in, faces);
  return check_closed(mesh, faces);
}

std::string solid_fracture_refusal(SurfaceMesh& mesh, const Vec3& impact, const SolidFractureOptions& options,
                                   FaceBvh* bvh) {
  return solid_fracture_check(mesh, impact, options, bvh).message;
}

SolidFractureResult fracture_solid(SurfaceMesh& mesh, const Vec3& impact, const SolidFractureOptions& o,
                                   FaceBvh* bvh) {
  SolidFractureResult result;
  Clock::time_point t = Clock::now();
  Setup s;
  if (!setup(mesh, impact, o, bvh, s)) throw InvalidInputError("fracture_solid: " + s.refusal);
  if (mesh.face_properties().find_base(kSubmeshProperty) &&
      !mesh.get_face_property<std::int32_t>(kSubmeshProperty))
    throw InvalidInputError(std::string("fracture_solid: the face property \"") + kSubmeshProperty +
                            "\" is not of type std::int32_t");
  if (mesh.face_properties().find_base(kInnerProperty) &&
      !mesh.get_face_property<std::uint8_t>(kInnerProperty))
    throw InvalidInputError(std::string("fracture_solid: the face property \"") + kInnerProperty +
                            "\" is not of type std::uint8_t");
  result.impact_face = s.hit.face;
  result.impact_point = s.hit.point;
  result.radius = s.radius;
  result.seconds.locate = seconds_since(t);

  StrikeInput in{mesh, *s.tree, to_double(s.hit.point), s.region_radius, s.material, o};
  // The region's faces, checked closed before anything else.
  std::vector<Face> faces;
  region_faces(in, faces);
  if (SolidFractureCheck why = check_closed(mesh, faces); why.code != SolidRefusal::none)
    throw InvalidInputError("fracture_solid: " + why.message);

  Strike strike;
  bool made = false;
  for (int attempt = 0; attempt < kAttempts && !made; ++attempt) {
    strike = Strike{};
    made = compute_strike(in, faces, attempt == 0 ? 0.0 : kNudge * s.radius * attempt,
                          o.seed + static_cast<std::uint64_t>(attempt), strike);
  }
  result.seconds.cells = strike.seconds_cells;
  result.seconds.clip = strike.seconds_clip;
  result.seconds.cap = strike.seconds_cap;
  t = Clock::now();
  if (!made)
    throw InvalidInputError("fracture_solid: the pieces of the strike at " + point_text(s.hit.point) +
                            " could not be made closed (" + strike.failure +
                            "); the mesh is unchanged. Strike again a little elsewhere");
  if (strike.pieces.empty()) {
    result.seconds.assemble = seconds_since(t);
    return result;
  }
  const std::int32_t inner = inner_submesh_of(mesh, o.inner_submesh);
  result.pieces = assemble_pieces(in, strike, inner);
  result.seconds.assemble = seconds_since(t);
  // The pieces are separate meshes: they are measured while the remaining object is edited and
  // its tree updated.
  double edit = 0;
  measure_pieces(result.pieces, o, [&] {
    Clock::time_point e = Clock::now();
    apply_remaining(in, strike, inner);
    if (bvh) {
      bvh->update();
      bvh->note_closed(true);  // the remaining object is closed, as the mesh was
    }
    edit = seconds_since(e);
  });
  result.bonds = std::move(strike.bonds);
  result.seconds.assemble += edit;
  result.seconds.per_piece = std::max(0.0, seconds_since(t) - edit);
  return result;
}

}  // namespace hedge
