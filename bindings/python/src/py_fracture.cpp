// Mesh.fracture(): an impact breaks the mesh into shards, located through the mesh's one picking
// tree (binding::picking_tree), as the C ABI and the WebAssembly module do. Each shard is a
// hedge.Shard, a hedge.Mesh of its own with what the library reports of it (front centroid and area, mass
// properties, convex hull); the remaining mesh is the mesh itself, edited in place. A custom
// material is a dict in the schema of the CLI's material files (docs/fracture.md), parsed by the
// same parser (tools/hedge/material_json.cpp), so both take the same fields with the same checks.
#include <pybind11/stl.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "binding/errors.h"
#include "hedge/algorithms/fracture.h"
#include "hedge/error.h"
#include "material_json.h"
#include "py_args.h"
#include "py_support.h"

namespace hedge::python {

namespace {

//! A piece broken off by Mesh.fracture(): a mesh, with what the library reports of it.
class Shard : public Mesh {
 public:
  Shard(std::shared_ptr<State> state, const hedge::Shard& s, std::shared_ptr<State> hull)
      : Mesh(std::move(state)),
        centroid(s.centroid),
        area(s.area),
        closed(s.closed),
        mass(s.mass),
        shell_thickness(s.shell_thickness),
        hull_dimension(s.hull.dimension),
        hull_tolerance(s.hull.tolerance),
        hull(std::move(hull)) {}
  Vec3d centroid;
  double area;
  bool closed;
  MassProperties mass;
  double shell_thickness;
  HullDimension hull_dimension;
  double hull_tolerance;
  std::shared_ptr<State> hull;  //!< none when the hull has no faces (or hulls were not asked for)
};

//! The library's result with each shard's mesh (and hull) already moved into a state of its own,
//! made without the GIL.
struct Broken {
  FractureResult result;
  std::vector<std::shared_ptr<State>> meshes, hulls;
};

}  // namespace

const char* hull_dimension_name(HullDimension d) {
  static const char* const kNames[] = {"empty", "point", "segment", "flat", "solid"};
  return kNames[static_cast<int>(d)];
}

//! A custom material: the dict as JSON text, through the material files' parser.
static FractureMaterial material_from_dict(const py::dict& material, const std::string& call) {
  // numpy scalars and arrays (a grain given as an array) become Python numbers and lists.
  const py::cpp_function plain([call](const py::object& o) -> py::object {
    if (py::hasattr(o, "tolist")) return o.attr("tolist")();
    throw InvalidInputError(call + ": material: " + std::string(py::repr(o)) +
                            " is not a number, list or str");
  });
  py::dict fields(material);
  if (!fields.contains("name")) fields["name"] = "custom";
  std::string text;
  try {
    text = py::module_::import("json")
               .attr("dumps")(fields, py::arg("allow_nan") = false, py::arg("default") = plain)
               .cast<std::string>();
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ValueError) || e.matches(py::module_::import("hedge._errors").attr("HedgeError")))
      throw;
    throw InvalidInputError(call + ": material: every number must be finite, not NaN or infinite");
  }
  return cli::parse_material_json(text, call + ": material");
}

FractureMaterial fracture_material_arg(const py::object& material, const std::string& call) {
  if (py::isinstance<py::str>(material)) return fracture_material(material.cast<std::string>());
  if (py::isinstance<py::dict>(material)) return material_from_dict(material.cast<py::dict>(), call);
  std::string presets;
  for (const std::string& name : fracture_material_names()) presets += (presets.empty() ? "" : ", ") + name;
  throw InvalidInputError(call + ": material must be a preset name (" + presets + ") or a dict, not " +
                          std::string(py::str(material.get_type().attr("__name__"))));
}

std::uint64_t seed_arg(const py::object& seed, const std::string& call) {
  // Any integer (numpy's too, through __index__), but not a bool or a float.
  if (py::isinstance<py::bool_>(seed) || !PyIndex_Check(seed.ptr()))
    throw InvalidInputError(call + ": seed must be a whole number in [0, 2^64), not " +
                            std::string(py::str(seed.get_type().attr("__name__"))));
  const py::object whole = py::reinterpret_steal<py::object>(PyNumber_Index(seed.ptr()));
  if (!whole) throw py::error_already_set();
  const unsigned long long s = PyLong_AsUnsignedLongLong(whole.ptr());
  if (PyErr_Occurred()) {
    PyErr_Clear();
    throw InvalidInputError(call + ": seed must be a whole number in [0, 2^64), got " +
                            std::string(py::str(seed)));
  }
  return s;
}

namespace {

//! The break radius's units by name.
FractureUnits units_named(const std::string& name) {
  for (FractureUnits u :
       {FractureUnits::diagonal_fraction, FractureUnits::model, FractureUnits::edge_lengths})
    if (name == fracture_units_name(u)) return u;
  throw InvalidInputError("fracture: units must be 'diagonal_fraction', 'model' or 'edge_lengths', not '" +
                          name + "'");
}

//! The keyword options of Mesh.fracture() besides the material and the seed.
struct Keywords {
  double break_radius;
  std::optional<std::string> units;
  double radius, thickness, relative_thickness;
  std::int32_t inner_submesh;
  double density, shell_thickness, tolerance;
  bool hulls;
};

//! The options of Mesh.fracture(), checked where the library does not check them itself.
FractureOptions fracture_options(const py::object& material, const py::object& seed, const Keywords& k) {
  FractureOptions o;
  o.material = fracture_material_arg(material, "fracture");  // lists the presets otherwise
  // None and 0: the material's own; anything else is checked by fracture() (finite, positive).
  if (k.units) o.material.units = units_named(*k.units);
  if (k.radius != 0) o.material.radius = k.radius;
  // 0: as above; anything else is checked (finite, positive) by the scaling.
  if (k.break_radius != 0) o.material = fracture_material_at_radius(o.material, k.break_radius);
  o.seed = seed_arg(seed, "fracture");
  o.thickness = k.thickness;
  o.relative_thickness = k.relative_thickness;
  o.inner_submesh = k.inner_submesh;
  o.density = k.density;
  o.shell_thickness = k.shell_thickness;
  o.tolerance = k.tolerance;
  o.hulls = k.hulls;
  return o;
}

std::shared_ptr<State> state_of(SurfaceMesh&& mesh) {
  auto state = std::make_shared<State>();
  state->mesh = std::move(mesh);
  return state;
}

py::list fracture(const Mesh& self, const py::object& point, const py::object& material,
                  const py::object& seed, double break_radius, std::optional<std::string> units,
                  double radius, double thickness, double relative_thickness, std::int32_t inner_submesh,
                  double density, double shell_thickness, double tolerance, bool hulls) {
  const Vec3 impact = point3(point, "fracture", "point");
  const FractureOptions options =
      fracture_options(material, seed,
                       {break_radius, std::move(units), radius, thickness, relative_thickness, inner_submesh,
                        density, shell_thickness, tolerance, hulls});
  Broken broken;
  {
    const auto use = self.use();
    require_no_views(*use, "fracture");  // the cuts and splits add elements
    py::gil_scoped_release unlocked;
    // Its InvalidInputError leaves the mesh unchanged; the tree is kept up to date by fracture().
    broken.result = hedge::fracture(use->mesh, impact, options, &binding::picking_tree(*use));
    for (hedge::Shard& s : broken.result.shards) {
      broken.meshes.push_back(state_of(std::move(s.mesh)));
      broken.hulls.push_back(s.hull.mesh.n_faces() > 0 ? state_of(std::move(s.hull.mesh)) : nullptr);
    }
  }
  py::list shards;
  for (std::size_t i = 0; i < broken.meshes.size(); ++i)
    shards.append(Shard(std::move(broken.meshes[i]), broken.result.shards[i], std::move(broken.hulls[i])));
  return shards;
}

}  // namespace

void bind_fracture(py::module_& m, py::class_<Mesh>& mesh) {
  py::class_<Shard, Mesh>(m, "Shard",
                          "A piece broken off by Mesh.fracture(): a Mesh of its own (every Mesh method "
                          "works on it), with what the library reports of it.")
      .def_property_readonly(
          "front_centroid", [](const Shard& s) { return vec3_array(s.centroid); },
          "Area-weighted centroid of the broken faces (the front), a (3,) float64 array (the C++ "
          "Shard::centroid; centroid is not a Mesh method's name).")
      .def_property_readonly(
          "front_area", [](const Shard& s) { return s.area; },
          "Area of the broken faces (the front only; Mesh.area() is the whole shard's area).")
      .def_property_readonly(
          "closed", [](const Shard& s) { return s.closed; },
          "True when the shard has no boundary (it was given a thickness): a solid with mass.")
      .def_property_readonly(
          "mass",
          [](const Shard& s) -> py::object {
            if (!(s.mass.mass > 0)) return py::none();  // no area (or a folded solid): nothing to weigh
            return mass_properties_dict(s.mass);
          },
          "The mass properties at the fracture's density (the C++ Shard::mass): of the closed solid "
          "(Mesh.mass_properties(density) computes them afresh), or for an open shard (closed is "
          "False) of its surface as a thin shell shell_thickness thick. A dict of volume, mass, "
          "centre_of_mass (3,), inertia (3, 3) about the centre of mass, "
          "principal_moments (3,) ascending and principal_axes (3, 3), one unit axis "
          "a row, a right-handed frame. None only for a shard without area.")
      .def_property_readonly(
          "shell_thickness", [](const Shard& s) { return s.shell_thickness; },
          "The thickness of the shell an open shard is weighed as (model units); 0 when closed.")
      .def_property_readonly(
          "hull",
          [](const Shard& s) -> py::object {
            if (!s.hull) return py::none();
            return py::cast(Mesh(s.hull));
          },
          "The convex hull of the shard's vertices as a Mesh (closed, outward triangles), for a "
          "collider; None when it has no faces or hulls=False.")
      .def_property_readonly(
          "hull_dimension", [](const Shard& s) { return hull_dimension_name(s.hull_dimension); },
          "What the shard's vertices span: 'empty', 'point', 'segment', 'flat' (the hull is given a "
          "thickness) or 'solid'.")
      .def_property_readonly(
          "hull_tolerance", [](const Shard& s) { return s.hull_tolerance; },
          "Every vertex lies inside the hull or within this distance of it.");
  mesh.def("fracture", &fracture, py::arg("point"), py::arg("material") = "glass", py::kw_only(),
           py::arg("seed") = 0, py::arg("break_radius") = 0.0, py::arg("units") = py::none(),
           py::arg("radius") = 0.0, py::arg("thickness") = 0.0, py::arg("relative_thickness") = 0.0,
           py::arg("inner_submesh") = -1, py::arg("density") = 1.0, py::arg("shell_thickness") = 0.0,
           py::arg("tolerance") = 0.0, py::arg("hulls") = true,
           "Breaks the mesh at point (3 numbers, within tolerance of the surface) into shards and "
           "returns them as a list of Shard (each a Mesh, with front_centroid, front_area, closed, "
           "mass and hull), in the order of their break points. The broken faces leave "
           "this mesh, which is edited in place. material: 'glass', 'stone', 'wood', 'ice', or a dict "
           "{name, rings: [{points, spacing, jitter}], grain, grain_stretch, refine_edge, units, "
           "radius} as the CLI's material files (docs/fracture.md). seed: a whole number; the same "
           "mesh, point, options and seed give the same shards. The break radius (the outer ring's) "
           "is the material's radius in its units: for the presets a fraction of the mesh's "
           "bounding-box diagonal (glass 0.13, stone 0.14, wood and ice 0.11), so the same share "
           "breaks at any resolution. units ('diagonal_fraction', 'model', 'edge_lengths') and "
           "radius > 0 replace the material's; break_radius > 0 sets it in model units instead. "
           "thickness > 0 (model units) or relative_thickness > 0 (a fraction of the break radius): "
           "each shard becomes a closed solid with mass properties at density; its added faces get "
           "inner_submesh in 'f:submesh' (-1: one more than the largest). Open shards weigh as a "
           "thin shell shell_thickness thick (0: a twentieth of the break radius). hulls: compute "
           "each shard's convex hull. Located through the mesh's picking "
           "tree, so a strike costs the broken area. InvalidArgumentError (the mesh unchanged) for a "
           "point off the surface or not finite, an unknown material or a bad option; "
           "ViewsExportedError while numpy views are alive. Releases the GIL.");
}

}  // namespace hedge::python
