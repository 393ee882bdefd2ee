// The whole-mesh algorithms of the Python Mesh: subdivision, smoothing, decimation, garbage
// collection and reordering, normals, geometry (area, volume, bounding box, mass properties), the
// convex hull, and hedge.hausdorff_distance.
//
// Every algorithm converts its Python arguments first, then releases the GIL while the library
// works. Those that may reallocate or renumber the mesh's arrays (subdivide, decimate,
// garbage_collection, reorder) call require_no_views() first. decimate, garbage_collection and
// reorder do not give the strong guarantee themselves, so they run under the binding core's
// with_rollback(): an error leaves the mesh as it was, as in the C ABI and the WebAssembly module.
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "binding/names.h"
#include "binding/rollback.h"
#include "hedge/algorithms/convex_hull.h"
#include "hedge/algorithms/decimate.h"
#include "hedge/algorithms/distance.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/mass_properties.h"
#include "hedge/algorithms/normals.h"
#include "hedge/algorithms/reorder.h"
#include "hedge/algorithms/smooth.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/error.h"
#include "py_args.h"
#include "py_support.h"

namespace hedge::python {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

//! An old-to-new map as an int32 array (-1 for a removed element).
py::array_t<std::int32_t> map_array(const std::vector<Index>& map) {
  py::array_t<std::int32_t> out(static_cast<py::ssize_t>(map.size()));
  std::int32_t* p = out.mutable_data();
  for (std::size_t i = 0; i < map.size(); ++i)
    p[i] = map[i] == kInvalidIndex ? -1 : static_cast<std::int32_t>(map[i]);
  return out;
}

py::dict maps_dict(const GarbageMaps& maps) {
  py::dict d;
  d["vertices"] = map_array(maps.vertices);
  d["halfedges"] = map_array(maps.halfedges);
  d["edges"] = map_array(maps.edges);
  d["faces"] = map_array(maps.faces);
  return d;
}

//! A Vec3 property as a fresh (slots, 3) float32 array; rows of dead slots (live(i) false) are NaN.
template <typename Values, typename Live>
py::array_t<float> rows_copy(const Values& values, Live&& live) {
  const auto n = static_cast<py::ssize_t>(values.size());
  py::array_t<float> out({n, py::ssize_t(3)});
  float* p = out.mutable_data();
  for (py::ssize_t i = 0; i < n; ++i) {
    const bool ok = live(static_cast<Index>(i));
    const Vec3& v = values[static_cast<std::size_t>(i)];
    p[3 * i] = ok ? v.x : NAN, p[3 * i + 1] = ok ? v.y : NAN, p[3 * i + 2] = ok ? v.z : NAN;
  }
  return out;
}

void subdivide(const Mesh& self, const std::string& scheme, int steps) {
  const Subdivision s = binding::parse_subdivision(scheme);
  const auto use = self.use();
  require_no_views(*use, "subdivide");
  py::gil_scoped_release unlocked;
  hedge::subdivide(use->mesh, s, steps);  // strong guarantee: no rollback needed
}

void smooth(const Mesh& self, const std::string& method, int iterations, double lambda, double mu,
            bool fix_boundary, const py::object& mask) {
  SmoothOptions o;
  o.method = binding::parse_smooth_method(method);
  o.iterations = iterations;
  o.lambda = lambda;
  o.mu = mu;
  o.fix_boundary = fix_boundary;
  const auto use = self.use();
  std::vector<std::uint8_t> chosen;
  if (!mask.is_none()) {
    chosen = slot_mask(mask, use->mesh.vertex_slots(), "smooth", "mask");
    // The library reads an empty mask as "every vertex": a mesh of no slots has nothing to move.
    if (chosen.empty()) return;
  }
  o.mask = chosen;
  py::gil_scoped_release unlocked;
  hedge::smooth(use->mesh, o);  // positions only: the views stay valid and see the result
}

py::dict decimate(const Mesh& self, std::optional<std::int64_t> target_faces_arg,
                  std::optional<std::int64_t> target_vertices_arg, std::optional<double> ratio,
                  std::optional<double> max_error, double boundary_weight, double feature_angle_degrees,
                  double feature_weight, bool keep_boundary, bool keep_seams, double attribute_weight,
                  double max_normal_change_degrees, bool relax_normal_change) {
  // With no target the library would collapse all it can: a mesh of thousands of faces to four.
  if (!target_faces_arg && !target_vertices_arg && !ratio && !max_error)
    throw InvalidInputError("decimate: give a target: target_faces, target_vertices, ratio or max_error");
  if (ratio && target_faces_arg)
    throw InvalidInputError("decimate: ratio and target_faces both set the count of faces; give one of them");
  const std::int64_t target_faces = target_faces_arg.value_or(0),
                     target_vertices = target_vertices_arg.value_or(0);
  if (target_faces < 0 || target_vertices < 0)
    throw InvalidInputError("decimate: target_faces and target_vertices must be counts (0 or more), got " +
                            std::to_string(target_faces) + " and " + std::to_string(target_vertices));
  if (ratio && !(*ratio > 0 && *ratio <= 1))
    throw InvalidInputError("decimate: ratio " + std::to_string(*ratio) + " is not in (0, 1]");
  DecimateOptions o;
  o.target_faces = static_cast<std::size_t>(target_faces);
  o.target_vertices = static_cast<std::size_t>(target_vertices);
  o.max_error = max_error.value_or(std::numeric_limits<double>::infinity());
  o.boundary_weight = boundary_weight;
  o.feature_angle_degrees = feature_angle_degrees;
  o.feature_weight = feature_weight;
  o.keep_boundary = keep_boundary;
  o.keep_seams = keep_seams;
  o.attribute_weight = attribute_weight;
  o.max_normal_change_degrees = max_normal_change_degrees;
  o.relax_normal_change = relax_normal_change;
  const auto use = self.use();
  require_no_views(*use, "decimate");
  SurfaceMesh& m = use->mesh;
  const std::size_t faces_before = m.n_faces(), vertices_before = m.n_vertices();
  if (ratio) {
    const double kept = std::round(*ratio * double(faces_before));
    o.target_faces = kept < 1 ? 1 : static_cast<std::size_t>(kept);
  }
  DecimateResult r;
  {
    py::gil_scoped_release unlocked;
    r = binding::with_rollback(m, [&] { return hedge::decimate(m, o); });
  }
  const bool faces_met = o.target_faces == 0 || r.faces <= o.target_faces;
  const bool vertices_met = o.target_vertices == 0 || r.vertices <= o.target_vertices;
  py::dict d;
  d["vertices"] = r.vertices;
  d["faces"] = r.faces;
  d["collapses"] = r.collapses;
  d["max_error"] = r.max_error;
  d["removed_faces"] = faces_before - r.faces;
  d["removed_vertices"] = vertices_before - r.vertices;
  // Whether a target was given and met (with none, the run goes as far as max_error and the legal
  // collapses allow); stop says why the run ended, refused how many attempts each check refused.
  d["target_reached"] = (o.target_faces != 0 || o.target_vertices != 0) && faces_met && vertices_met;
  d["stop"] = binding::name(r.stop);
  py::dict refused;
  refused["topology"] = r.refused.topology;
  refused["normal"] = r.refused.normal;
  refused["shape"] = r.refused.shape;
  d["refused"] = refused;
  return d;
}

py::dict garbage_collection(const Mesh& self) {
  const auto use = self.use();
  require_no_views(*use, "garbage_collection");
  SurfaceMesh& m = use->mesh;
  GarbageMaps maps;
  {
    py::gil_scoped_release unlocked;
    maps = binding::with_rollback(m, [&] { return m.garbage_collection(); });
  }
  return maps_dict(maps);
}

py::dict reorder(const Mesh& self, const std::string& ordering, std::int64_t cache_size) {
  const Ordering o = binding::parse_ordering(ordering);
  if (cache_size < 1 || cache_size > 1024)
    throw InvalidInputError("reorder: cache_size must be in 1..1024, got " + std::to_string(cache_size));
  const auto use = self.use();
  require_no_views(*use, "reorder");
  SurfaceMesh& m = use->mesh;
  GarbageMaps maps;
  {
    py::gil_scoped_release unlocked;
    maps =
        binding::with_rollback(m, [&] { return hedge::reorder(m, o, static_cast<std::size_t>(cache_size)); });
  }
  return maps_dict(maps);
}

py::array_t<float> face_normals(const Mesh& self) {
  const auto use = self.use();
  SurfaceMesh& m = use->mesh;
  std::optional<FaceProperty<Vec3>> normals;
  {
    py::gil_scoped_release unlocked;
    normals = compute_face_normals(m);
  }
  return rows_copy(normals->vector(), [&](Index i) { return !m.is_deleted(Face(i)); });
}

py::array_t<float> vertex_normals(const Mesh& self, const std::string& weighting) {
  const NormalWeighting w = binding::parse_normal_weighting(weighting);
  const auto use = self.use();
  SurfaceMesh& m = use->mesh;
  std::optional<VertexProperty<Vec3>> normals;
  {
    py::gil_scoped_release unlocked;
    normals = compute_vertex_normals(m, w);
  }
  return rows_copy(normals->vector(), [&](Index i) { return !m.is_deleted(Vertex(i)); });
}

py::array_t<float> corner_normals(const Mesh& self, double crease_degrees, const std::string& weighting) {
  const NormalWeighting w = binding::parse_normal_weighting(weighting);
  const auto use = self.use();
  SurfaceMesh& m = use->mesh;
  std::optional<HalfedgeProperty<Vec3>> normals;
  {
    py::gil_scoped_release unlocked;
    normals = compute_corner_normals(m, crease_degrees, w);
  }
  return rows_copy(normals->vector(), [&](Index i) { return !m.is_deleted(Edge(i >> 1)); });
}

py::array_t<double> bounding_box_of(const Mesh& self) {
  const auto use = self.use();
  const BoundingBox box = bounding_box(use->mesh);
  py::array_t<double> out({py::ssize_t(2), py::ssize_t(3)});
  double* p = out.mutable_data();
  for (int a = 0; a < 3; ++a) {
    p[a] = box.empty ? kNaN : box.min[a];
    p[3 + a] = box.empty ? kNaN : box.max[a];
  }
  return out;
}

py::dict mass_properties_of(const Mesh& self, double density) {
  const auto use = self.use();
  MassProperties mp;
  {
    py::gil_scoped_release unlocked;
    mp = mass_properties(use->mesh, density);
  }
  return mass_properties_dict(mp);
}

Mesh convex_hull_of(const Mesh& self, std::int64_t max_vertices, double relative_tolerance,
                    double flat_thickness) {
  if (max_vertices < 0)
    throw InvalidInputError("convex_hull: max_vertices must be 0 (no limit) or more, got " +
                            std::to_string(max_vertices));
  ConvexHullOptions o;
  o.max_vertices = static_cast<std::size_t>(max_vertices);
  o.relative_tolerance = relative_tolerance;
  o.flat_thickness = flat_thickness;
  auto state = std::make_shared<State>();
  const auto use = self.use();
  {
    py::gil_scoped_release unlocked;
    const SurfaceMesh& m = use->mesh;
    std::vector<Vec3> points;
    points.reserve(m.n_vertices());
    for (const Vertex v : m.vertices()) points.push_back(m.position(v));
    state->mesh = std::move(convex_hull(points, o).mesh);
  }
  return Mesh(std::move(state));
}

py::dict one_sided(const OneSidedDistance& d) {
  py::dict out;
  out["max"] = d.max;
  out["mean"] = d.mean;
  out["farthest"] = vec3_array(d.farthest);
  out["points"] = d.points;
  return out;
}

py::dict hausdorff(const Mesh& a, const Mesh& b, std::int64_t samples, std::uint64_t seed,
                   std::int64_t threads) {
  if (samples < 0)
    throw InvalidInputError("hausdorff_distance: samples must be 0 or more, got " + std::to_string(samples));
  if (static_cast<std::uint64_t>(samples) > kMaxDistanceSamples)
    throw InvalidInputError("hausdorff_distance: samples must be at most " +
                            std::to_string(kMaxDistanceSamples) + ", got " + std::to_string(samples) +
                            "; draw fewer");
  const DistanceOptions o{.samples = static_cast<std::size_t>(samples),
                          .seed = seed,
                          .threads = binding::thread_count(threads, "hausdorff_distance: threads")};
  // A mesh measured against itself is one use: a second would be refused as busy.
  const auto use_a = a.use();
  std::optional<binding::MeshUse<State>> use_b;
  if (b.state() != a.state()) use_b.emplace(b.use());
  const SurfaceMesh& mb = use_b ? (*use_b)->mesh : use_a->mesh;
  HausdorffDistance d;
  {
    py::gil_scoped_release unlocked;
    d = hausdorff_distance(use_a->mesh, mb, o);
  }
  py::dict out;
  out["distance"] = d.distance;
  out["mean"] = d.mean;
  out["a_to_b"] = one_sided(d.a_to_b);
  out["b_to_a"] = one_sided(d.b_to_a);
  return out;
}

}  // namespace

void bind_algorithms(py::class_<Mesh>& mesh, py::module_& m) {
  mesh.def("subdivide", &subdivide, py::arg("scheme") = "loop", py::arg("steps") = 1,
           "Refines every face `steps` times by the scheme: 'loop', 'midpoint', 'sqrt3' (triangles "
           "only), 'catmull-clark' or 'split-faces'. Renumbers every element. Raises "
           "ViewsExportedError while views are alive, InvalidArgumentError for an unknown scheme, "
           "negative steps or a face the scheme cannot take; the mesh is then unchanged. Releases "
           "the GIL.")
      .def("smooth", &smooth, py::arg("method") = "uniform", py::arg("iterations") = 10,
           py::arg("lambda_") = 0.5, py::arg("mu") = -0.53, py::arg("fix_boundary") = true,
           py::arg("mask") = py::none(),
           "Moves the vertices toward the average of their neighbours. method: 'uniform', 'taubin' "
           "(lambda_ then the inflating mu per iteration), 'cotangent' or 'implicit' (lambda_ is then "
           "the time step; both need triangles). fix_boundary keeps boundary vertices in place, "
           "otherwise they slide along the boundary. mask: one entry per vertex slot, only nonzero "
           "ones move. Only positions change, so views stay valid. Illegal options raise "
           "InvalidArgumentError with the mesh unchanged. Releases the GIL.")
      .def("decimate", &decimate, py::kw_only(), py::arg("target_faces") = py::none(),
           py::arg("target_vertices") = py::none(), py::arg("ratio") = py::none(),
           py::arg("max_error") = py::none(), py::arg("boundary_weight") = 1.0,
           py::arg("feature_angle_degrees") = 60.0, py::arg("feature_weight") = 1.0,
           py::arg("keep_boundary") = false, py::arg("keep_seams") = true, py::arg("attribute_weight") = 0.0,
           py::arg("max_normal_change_degrees") = 60.0, py::arg("relax_normal_change") = true,
           "Decimates a triangle mesh by quadric-ranked edge collapses until it has at most "
           "target_faces faces and target_vertices vertices (each when given; ratio, instead of "
           "target_faces, sets it to that share of the faces), or the next collapse would move the surface "
           "by more than max_error, or no legal collapse is left. Garbage is collected at the end "
           "(indices change). relax_normal_change: should max_normal_change_degrees (below 90) alone "
           "stop the run short of its target, raise it to 90 for the rest (False: it holds to the end). "
           "Returns a dict: vertices, faces (left), collapses, max_error (the "
           "largest error of a collapse done), removed_faces, removed_vertices, target_reached "
           "(a target was given and met), stop (why the run ended: 'target_reached', 'error_bound' or "
           "'no_legal_collapse') and refused (a dict of the collapse attempts each check refused: "
           "topology, normal, shape; an edge retried in a later pass counts again). On "
           "any error the mesh is unchanged. Raises InvalidArgumentError if none of target_faces, "
           "target_vertices, ratio and max_error is given, or ratio with target_faces; "
           "ViewsExportedError while views are alive. "
           "Releases the GIL.")
      .def("garbage_collection", &garbage_collection,
           "Removes deleted elements and compacts every array; indices change. Returns the "
           "old-to-new maps as a dict of int32 arrays (vertices, halfedges, edges, faces; -1 for a "
           "removed element). On an error the mesh is unchanged. Raises ViewsExportedError while "
           "views are alive. Releases the GIL.")
      .def("reorder", &reorder, py::arg("ordering") = "spatial", py::arg("cache_size") = 16,
           "Renumbers the elements so that memory order serves traversals: 'spatial' (a Morton "
           "curve) or 'vertex-cache' (faces for a GPU vertex cache of cache_size entries, vertices "
           "by first use); garbage is collected too. Returns the old-to-new maps as "
           "garbage_collection() does. Raises ViewsExportedError while views are alive. Releases "
           "the GIL.")
      .def(
          "cache_miss_ratio",
          [](const Mesh& self, std::int64_t cache_size) {
            if (cache_size < 1 || cache_size > 1024)
              throw InvalidInputError("cache_miss_ratio: cache_size must be in 1..1024, got " +
                                      std::to_string(cache_size));
            const auto use = self.use();
            py::gil_scoped_release unlocked;
            return average_cache_miss_ratio(use->mesh, static_cast<std::size_t>(cache_size));
          },
          py::arg("cache_size") = 16,
          "The average cache miss ratio of drawing the faces in index order (each face a fan of "
          "triangles) through a first-in first-out vertex cache of cache_size entries: vertex loads "
          "per triangle, 3 at worst. reorder('vertex-cache') lowers it. Releases the GIL.")
      .def("face_normals", &face_normals,
           "Unit face normals (Newell's method; zero for a degenerate face) as a fresh (face_slots, 3) "
           "float32 array, NaN rows for deleted slots, like positions one row per slot. Also stored "
           "in the face property 'f:normal'. Releases the GIL.")
      .def("vertex_normals", &vertex_normals, py::arg("weighting") = "area",
           "Unit vertex normals, the faces around each vertex weighted by 'area', 'angle' or "
           "'uniform', as a fresh (vertex_slots, 3) float32 array, NaN rows for deleted slots; zero "
           "for an isolated vertex. Also stored in the vertex property 'v:normal' (which write() "
           "exports). Releases the GIL.")
      .def("corner_normals", &corner_normals, py::arg("crease_degrees") = 180.0,
           py::arg("weighting") = "angle",
           "Normals of face corners (the corner of face(h) at to_vertex(h)), smooth within wedges "
           "split at edges sharper than crease_degrees (0: flat, 180: smooth), as a fresh "
           "(halfedge_slots, 3) float32 array; zero on boundary half-edges, NaN for deleted slots. "
           "Also stored in 'h:normal'. Releases the GIL.")
      .def(
          "area",
          [](const Mesh& self) {
            const auto use = self.use();
            py::gil_scoped_release unlocked;
            return surface_area(use->mesh);
          },
          "The total area of the faces. Releases the GIL.")
      .def(
          "volume",
          [](const Mesh& self) {
            const auto use = self.use();
            py::gil_scoped_release unlocked;
            return volume(use->mesh);
          },
          "The signed volume the closed surface encloses (negative if inside out). Raises "
          "InvalidArgumentError for a mesh with a boundary. Releases the GIL.")
      .def("bounding_box", &bounding_box_of,
           "The axis-aligned box around the live vertices as a (2, 3) float64 array [min, max]; NaN "
           "for a mesh without vertices.")
      .def("mass_properties", &mass_properties_of, py::arg("density") = 1.0,
           "Mass properties of the solid a closed, outward-wound triangle mesh bounds, at uniform "
           "density: a dict of mass, volume, centre_of_mass (3,), inertia (3, 3, about the centre of "
           "mass), principal_moments (3,, ascending) and principal_axes (3, 3, row i the axis of "
           "moment i). Raises InvalidArgumentError for an open, non-triangle or inside-out mesh. "
           "Releases the GIL.")
      .def("convex_hull", &convex_hull_of, py::kw_only(), py::arg("max_vertices") = 0,
           py::arg("relative_tolerance") = 1e-9, py::arg("flat_thickness") = 1e-3,
           "The convex hull of the live vertices as a new closed triangle Mesh (quickhull). A flat "
           "point set gets a thin prism flat_thickness (relative to the box diagonal) thick; fewer "
           "than three non-collinear points give an empty mesh. max_vertices > 0 (at least 4) "
           "limits the hull's vertices. Releases the GIL.");
  m.def("hausdorff_distance", &hausdorff, py::arg("a"), py::arg("b"), py::kw_only(),
        py::arg("samples") = 100000, py::arg("seed") = 1, py::arg("threads") = 2,
        "The symmetric sampled Hausdorff distance between meshes a and b: each mesh's vertices and "
        "`samples` seeded points on its faces are measured against the other surface. Returns a "
        "dict: distance (the larger one-sided maximum), mean, and a_to_b, b_to_a (dicts of max, "
        "mean, farthest point, points). samples at most 100,000,000; threads 0 (every core) to 1024, "
        "as render takes them. Raises InvalidArgumentError for a mesh without faces. Releases the GIL.");
}

}  // namespace hedge::python
