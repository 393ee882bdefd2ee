// Mesh.fracture_solid(): an impact breaks a closed mesh into closed pieces, located through the
// mesh's one picking tree (binding::picking_tree), as the WebAssembly module does. Each piece is a
// hedge.Piece, a hedge.Mesh of its own with what the library reports of it (volume, cap area, mass
// properties, convex hull); the bonds say which pieces touch and by how much cap; the remaining
// object is the mesh itself, edited in place. Mesh.solid_fracture_refusal() says why a strike would
// be refused.
#include <pybind11/stl.h>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "binding/names.h"
#include "hedge/algorithms/fracture_solid.h"
#include "hedge/error.h"
#include "py_args.h"
#include "py_support.h"

namespace hedge::python {

namespace {

//! A piece broken off by Mesh.fracture_solid(): a closed mesh, with what the library reports of it.
class Piece : public Mesh {
 public:
  Piece(std::shared_ptr<State> state, const SolidPiece& p, std::shared_ptr<State> hull)
      : Mesh(std::move(state)),
        volume(p.volume),
        cap_area(p.cap_area),
        mass(p.mass),
        hull_dimension(p.hull.dimension),
        hull_tolerance(p.hull.tolerance),
        hull(std::move(hull)) {}
  double volume;
  double cap_area;
  MassProperties mass;
  HullDimension hull_dimension;
  double hull_tolerance;
  std::shared_ptr<State> hull;  //!< none when the hull has no faces (or hulls were not asked for)
};

//! The options of Mesh.fracture_solid() and solid_fracture_refusal(); the library checks the values.
SolidFractureOptions solid_options(const char* call, const py::object& material, const py::object& seed,
                                   double radius, double radius_fraction, std::int32_t inner_submesh,
                                   double density, double tolerance, bool hulls) {
  SolidFractureOptions o;
  o.material = fracture_material_arg(material, call);
  o.seed = seed_arg(seed, call);
  o.radius = radius;
  o.radius_fraction = radius_fraction;
  o.inner_submesh = inner_submesh;
  o.density = density;
  o.tolerance = tolerance;
  o.hulls = hulls;
  return o;
}

std::shared_ptr<State> state_of(SurfaceMesh&& mesh) {
  auto state = std::make_shared<State>();
  state->mesh = std::move(mesh);
  return state;
}

//! solid_fracture_check() through the mesh's picking tree, without the GIL. Building or updating
//! the tree changes no element: numpy views may stay.
SolidFractureCheck check(const Mesh& self, const Vec3& impact, const SolidFractureOptions& options) {
  const auto use = self.use();
  py::gil_scoped_release unlocked;
  return hedge::solid_fracture_check(use->mesh, impact, options, &binding::picking_tree(*use));
}

py::tuple fracture_solid(const Mesh& self, const py::object& point, const py::object& material,
                         const py::object& seed, double radius, double radius_fraction,
                         std::int32_t inner_submesh, double density, double tolerance, bool hulls,
                         const std::string& kind, const py::object& surface) {
  if (kind != "solid" && kind != "auto")
    throw InvalidInputError("fracture_solid: unknown kind '" + kind + "' (solid, auto)");
  if (!surface.is_none() && !py::isinstance<py::dict>(surface))
    throw InvalidInputError("fracture_solid: surface must be a dict of fracture() options");
  const Vec3 impact = point3(point, "fracture_solid", "point");
  const SolidFractureOptions options = solid_options(
      "fracture_solid", material, seed, radius, radius_fraction, inner_submesh, density, tolerance, hulls);
  if (kind == "auto") {
    // Only the input's shape (open or non-manifold) sends a strike to surface fracture
    // (solid_refusal_falls_back()); a bad option or impact is an error, as it is with kind 'solid'.
    const SolidFractureCheck why = check(self, impact, options);
    if (solid_refusal_falls_back(why.code)) {
      py::dict kwargs;
      kwargs["seed"] = seed;
      kwargs["break_radius"] = radius;
      kwargs["density"] = density;
      kwargs["tolerance"] = tolerance;
      kwargs["hulls"] = hulls;
      if (!surface.is_none())
        for (const auto item : surface.cast<py::dict>()) kwargs[item.first] = item.second;
      const py::object shards = py::cast(self).attr("fracture")(point, material, **kwargs);
      return py::make_tuple(shards, py::str(why.message));
    }
  }
  SolidFractureResult result;
  std::vector<std::shared_ptr<State>> meshes, hull_meshes;
  {
    const auto use = self.use();
    require_no_views(*use, "fracture_solid");  // the cuts and caps add elements
    py::gil_scoped_release unlocked;
    // Its InvalidInputError leaves the mesh unchanged; the tree is kept up to date by fracture_solid().
    result = hedge::fracture_solid(use->mesh, impact, options, &binding::picking_tree(*use));
    for (SolidPiece& p : result.pieces) {
      meshes.push_back(state_of(std::move(p.mesh)));
      hull_meshes.push_back(p.hull.mesh.n_faces() > 0 ? state_of(std::move(p.hull.mesh)) : nullptr);
    }
  }
  py::list pieces;
  for (std::size_t i = 0; i < meshes.size(); ++i)
    pieces.append(Piece(std::move(meshes[i]), result.pieces[i], std::move(hull_meshes[i])));
  py::list bonds;
  for (const SolidBond& b : result.bonds)
    bonds.append(
        py::make_tuple(b.a, b.b == kSolidRemaining ? py::object(py::none()) : py::int_(b.b), b.area));
  return py::make_tuple(pieces, bonds);
}

py::object solid_fracture_refusal(const Mesh& self, const py::object& point, const py::object& material,
                                  const py::object& seed, double radius, double radius_fraction,
                                  std::int32_t inner_submesh, double density, double tolerance) {
  const Vec3 impact = point3(point, "solid_fracture_refusal", "point");
  const SolidFractureOptions options =
      solid_options("solid_fracture_refusal", material, seed, radius, radius_fraction, inner_submesh, density,
                    tolerance, false);
  const SolidFractureCheck why = check(self, impact, options);
  if (why.code == SolidRefusal::none) return py::none();
  return py::str(why.message);
}

std::string solid_fracture_refusal_code(const Mesh& self, const py::object& point, const py::object& material,
                                        const py::object& seed, double radius, double radius_fraction,
                                        std::int32_t inner_submesh, double density, double tolerance) {
  const Vec3 impact = point3(point, "solid_fracture_refusal_code", "point");
  const SolidFractureOptions options =
      solid_options("solid_fracture_refusal_code", material, seed, radius, radius_fraction, inner_submesh,
                    density, tolerance, false);
  return binding::name(check(self, impact, options).code);
}

}  // namespace

void bind_fracture_solid(py::module_& m, py::class_<Mesh>& mesh) {
  py::class_<Piece, Mesh>(m, "Piece",
                          "A closed piece broken off by Mesh.fracture_solid(): a Mesh of its own (every "
                          "Mesh method works on it), with what the library reports of it. Its outer faces "
                          "keep the struck mesh's properties; its cap faces have 'f:inner' = 1 and the "
                          "inner submesh in 'f:submesh'.")
      .def_property_readonly(
          "volume", [](const Piece& p) { return p.volume; }, "The enclosed volume, positive.")
      .def_property_readonly(
          "cap_area", [](const Piece& p) { return p.cap_area; },
          "The area of the cap (inner) faces, the cut surface.")
      .def_property_readonly(
          "mass", [](const Piece& p) { return mass_properties_dict(p.mass); },
          "The mass properties at the fracture's density: a dict of volume, mass, centre_of_mass "
          "(3,), inertia (3, 3) about the centre of mass, principal_moments (3,) ascending and "
          "principal_axes (3, 3), one unit axis a row, a right-handed frame.")
      .def_property_readonly(
          "hull",
          [](const Piece& p) -> py::object {
            if (!p.hull) return py::none();
            return py::cast(Mesh(p.hull));
          },
          "The convex hull of the piece's vertices as a Mesh (closed, outward triangles), for a "
          "collider; None when hulls=False.")
      .def_property_readonly(
          "hull_dimension", [](const Piece& p) { return hull_dimension_name(p.hull_dimension); },
          "What the piece's vertices span: 'solid' for a piece ('empty' without a hull).")
      .def_property_readonly(
          "hull_tolerance", [](const Piece& p) { return p.hull_tolerance; },
          "Every vertex lies inside the hull or within this distance of it.");
  mesh.def("fracture_solid", &fracture_solid, py::arg("point"), py::arg("material") = "stone", py::kw_only(),
           py::arg("seed") = 0, py::arg("radius") = 0.0, py::arg("radius_fraction") = 0.25,
           py::arg("inner_submesh") = -1, py::arg("density") = 1.0, py::arg("tolerance") = 0.0,
           py::arg("hulls") = true, py::arg("kind") = "solid", py::arg("surface") = py::none(),
           "Breaks the closed mesh at point (3 numbers, within tolerance of the surface) into closed "
           "pieces with capped inner faces (docs/fracture.md) and returns (pieces, bonds): pieces a "
           "list of Piece (each a closed Mesh, with volume, cap_area, mass and hull) in the order of "
           "their break points; bonds a list of (a, b, area), pieces a < b sharing area of cap, b None "
           "when piece a touches the remaining object, sorted. This mesh, edited in place, becomes the "
           "remaining object, closed too. material: 'glass', 'stone', 'wood', 'ice', or a dict as for "
           "fracture(). radius: the break radius in model units; 0: radius_fraction times the "
           "diagonal of the mesh's bounding box. seed: a whole number; the same mesh, point, options "
           "and seed give the same pieces. The caps get inner_submesh in 'f:submesh' (-1: one more "
           "than the largest) and UVs by planar projection in model units. density: for the mass "
           "properties. hulls: compute each piece's convex hull. kind: 'solid', or 'auto' to break an "
           "open or non-manifold mesh by surface fracture instead (solid_fracture_refusal_code() "
           "'open' or 'non_manifold'; any other refusal raises): the result then is (shards, why), "
           "fracture()'s list of Shard and the refusal (a str) that sent it there in place of the "
           "bonds; surface: a dict of more fracture() options for that case, e.g. {'thickness': 0.1} "
           "(a bad option or point raises as with 'solid'). Located through the mesh's picking "
           "tree, so a strike costs the broken region. InvalidArgumentError (the mesh unchanged) for "
           "a mesh open anywhere or non-manifold near the impact with kind 'solid' (solid_fracture_refusal() "
           "says why without raising; fracture() or kind 'auto' breaks such a mesh), an unknown kind, a "
           "point off the surface or not finite, an "
           "unknown material or a bad option; ViewsExportedError while numpy views are alive. "
           "Releases the GIL.");
  mesh.def("solid_fracture_refusal", &solid_fracture_refusal, py::arg("point"), py::arg("material") = "stone",
           py::kw_only(), py::arg("seed") = 0, py::arg("radius") = 0.0, py::arg("radius_fraction") = 0.25,
           py::arg("inner_submesh") = -1, py::arg("density") = 1.0, py::arg("tolerance") = 0.0,
           "Why fracture_solid() with these arguments would be refused, or None if it would not: the "
           "mesh open anywhere or non-manifold near the impact (naming a boundary edge), no face within "
           "tolerance of point, an illegal option. Checks only the faces of the broken region, so it "
           "costs the region. Use it to choose between fracture_solid() and fracture() (surface "
           "fracture, which breaks open meshes). Releases the GIL.");
  mesh.def("solid_fracture_refusal_code", &solid_fracture_refusal_code, py::arg("point"),
           py::arg("material") = "stone", py::kw_only(), py::arg("seed") = 0, py::arg("radius") = 0.0,
           py::arg("radius_fraction") = 0.25, py::arg("inner_submesh") = -1, py::arg("density") = 1.0,
           py::arg("tolerance") = 0.0,
           "solid_fracture_refusal()'s answer as a code, the same in every binding: 'none' (no "
           "refusal), 'open', 'non_manifold' (the input's shape: fracture_solid(kind='auto') breaks "
           "these by surface fracture), or 'bad_option', 'bad_impact', 'off_surface', 'no_face', "
           "'bad_radius' (errors with either kind). Releases the GIL.");
}

}  // namespace hedge::python
