// Picking over many rays or points in one call: ray_cast and closest_point, through the mesh's one
// picking tree (binding::picking_tree), which follows the change log, so edits and
// positions_changed() keep it up to date at the cost of what changed. Every row is checked first
// (binding/picking.h): a NaN, an infinity or a zero direction is an error naming the row, not a
// miss. The GIL is released while the rows are checked and the tree is walked.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "binding/mesh_state.h"
#include "binding/picking.h"
#include "hedge/algorithms/locate.h"
#include "hedge/error.h"
#include "py_support.h"

namespace hedge::python {

namespace {

using Points = py::array_t<float, py::array::c_style | py::array::forcecast>;

//! `a` as an (n, 3) float32 array; `what` names it in the error.
Points rows_of_3(const py::object& a, const char* call, const char* what) {
  Points p = Points::ensure(a);
  if (!p || p.ndim() != 2 || p.shape(1) != 3)
    throw InvalidInputError(std::string(call) + ": " + what + " must be an (n, 3) array of floats");
  return p;
}

Vec3 row(const Points& p, py::ssize_t i) {
  const float* q = p.data(i, 0);
  return Vec3{q[0], q[1], q[2]};
}

//! "CALL: WHAT[i]", the name of a row in an error.
std::string row_name(const char* call, const char* what, py::ssize_t i) {
  return std::string(call) + ": " + what + "[" + std::to_string(i) + "]";
}

py::tuple ray_cast(const Mesh& self, const py::object& origins, const py::object& directions) {
  const Points o = rows_of_3(origins, "ray_cast", "origins"),
               d = rows_of_3(directions, "ray_cast", "directions");
  if (o.shape(0) != d.shape(0))
    throw InvalidInputError("ray_cast: " + std::to_string(o.shape(0)) + " origins but " +
                            std::to_string(d.shape(0)) + " directions");
  const py::ssize_t n = o.shape(0);
  py::array_t<std::int32_t> faces(n);
  py::array_t<double> t(n);
  py::array_t<float> points({n, py::ssize_t(3)});
  std::int32_t* f_out = faces.mutable_data();
  double* t_out = t.mutable_data();
  float* p_out = points.mutable_data();
  const auto use = self.use();
  {
    py::gil_scoped_release unlocked;
    for (py::ssize_t i = 0; i < n; ++i) {
      binding::need_finite(row(o, i), row_name("ray_cast", "origins", i));
      binding::need_direction(row(d, i), row_name("ray_cast", "directions", i));
    }
    const FaceBvh& bvh = binding::picking_tree(*use);
    for (py::ssize_t i = 0; i < n; ++i) {
      const auto hit = bvh.first_hit(row(o, i), row(d, i));
      f_out[i] = hit ? static_cast<std::int32_t>(hit->face.idx()) : -1;
      t_out[i] = hit ? hit->t : std::numeric_limits<double>::quiet_NaN();
      const Vec3 p = hit ? hit->point : Vec3{NAN, NAN, NAN};
      p_out[3 * i] = p.x, p_out[3 * i + 1] = p.y, p_out[3 * i + 2] = p.z;
    }
  }
  return py::make_tuple(faces, t, points);
}

py::tuple closest_point(const Mesh& self, const py::object& queries) {
  const Points q = rows_of_3(queries, "closest_point", "points");
  const py::ssize_t n = q.shape(0);
  py::array_t<std::int32_t> faces(n);
  py::array_t<float> points({n, py::ssize_t(3)});
  py::array_t<double> distances(n);
  std::int32_t* f_out = faces.mutable_data();
  float* p_out = points.mutable_data();
  double* d_out = distances.mutable_data();
  const auto use = self.use();
  {
    py::gil_scoped_release unlocked;
    for (py::ssize_t i = 0; i < n; ++i)
      binding::need_finite(row(q, i), row_name("closest_point", "points", i));
    const FaceBvh& bvh = binding::picking_tree(*use);
    for (py::ssize_t i = 0; i < n; ++i) {
      const auto near = bvh.closest_point(row(q, i));
      f_out[i] = near ? static_cast<std::int32_t>(near->face.idx()) : -1;
      d_out[i] = near ? std::sqrt(near->squared_distance) : std::numeric_limits<double>::quiet_NaN();
      const Vec3 p = near ? near->point : Vec3{NAN, NAN, NAN};
      p_out[3 * i] = p.x, p_out[3 * i + 1] = p.y, p_out[3 * i + 2] = p.z;
    }
  }
  return py::make_tuple(faces, points, distances);
}

}  // namespace

void bind_picking(py::class_<Mesh>& mesh) {
  mesh.def("ray_cast", &ray_cast, py::arg("origins"), py::arg("directions"),
           "Casts n rays, given as (n, 3) arrays of origins and directions, against the faces. Returns "
           "(faces, t, points): the first face each ray hits (-1 for none), the ray parameter of the "
           "hit (point = origin + t * direction; NaN for none) and the (n, 3) hit points. A row that "
           "is not finite, or a zero direction, raises InvalidArgumentError naming it. Uses the "
           "mesh's picking tree, built on first use and kept up to date through the change log "
           "(call positions_changed() after writing positions). Releases the GIL.")
      .def("closest_point", &closest_point, py::arg("points"),
           "The nearest surface point to each of n query points (an (n, 3) array). Returns (faces, "
           "points, distances); -1 and NaN where the mesh has no face. A point that is not finite "
           "raises InvalidArgumentError naming its row. Releases the GIL.");
}

}  // namespace hedge::python
