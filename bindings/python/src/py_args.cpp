// Arguments as Python gives them and results as Python takes them, shared by the binding's files
// (py_args.h).
#include "py_args.h"

#include <cmath>
#include <string>

#include "binding/edits.h"
#include "binding/errors.h"
#include "hedge/error.h"

namespace hedge::python {

Vec3d point3d(const py::handle& p, const char* call, const char* what) {
  const std::string name = std::string(call) + ": " + what;
  const auto bad = [&] {
    binding::fail(HEDGE_ERROR_INVALID_ARGUMENT,
                  name + " must be 3 numbers x, y, z, got " + std::string(py::repr(p)));
  };
  if (py::isinstance<py::str>(p) || py::isinstance<py::bytes>(p)) bad();
  py::array_t<double, py::array::c_style | py::array::forcecast> a;
  try {
    a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(p);
  } catch (const py::error_already_set&) {
  }
  if (!a || a.ndim() != 1 || a.shape(0) != 3) bad();
  const double* q = a.data();
  const Vec3d v{q[0], q[1], q[2]};
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    binding::fail(HEDGE_ERROR_INVALID_ARGUMENT, name + " (" + std::to_string(v.x) + ", " +
                                                    std::to_string(v.y) + ", " + std::to_string(v.z) +
                                                    ") is not finite");
  return v;
}

Vec3 point3(const py::handle& p, const char* call, const char* what) {
  const Vec3d v = point3d(p, call, what);
  return binding::need_point(Vec3{float(v.x), float(v.y), float(v.z)},
                             (std::string(call) + ": " + what).c_str());
}

std::string fspath(const py::object& path) {
  const py::object p = py::module_::import("os").attr("fspath")(path);
  if (!py::isinstance<py::str>(p))
    throw InvalidInputError("a path must be a str or an os.PathLike of str, not bytes");
  return p.cast<std::string>();
}

py::array_t<double> vec3_array(const Vec3d& v) {
  py::array_t<double> out(3);
  double* p = out.mutable_data();
  p[0] = v.x, p[1] = v.y, p[2] = v.z;
  return out;
}

py::array_t<double> vec3_array(const Vec3& v) { return vec3_array(Vec3d{v.x, v.y, v.z}); }

py::dict mass_properties_dict(const MassProperties& mp) {
  py::array_t<double> inertia({py::ssize_t(3), py::ssize_t(3)}), axes({py::ssize_t(3), py::ssize_t(3)});
  double* in = inertia.mutable_data();
  double* ax = axes.mutable_data();
  for (int i = 0; i < 9; ++i) in[i] = mp.inertia[static_cast<std::size_t>(i)];
  for (int a = 0; a < 3; ++a) {
    const Vec3d& axis = mp.principal_axes[static_cast<std::size_t>(a)];
    ax[3 * a] = axis.x, ax[3 * a + 1] = axis.y, ax[3 * a + 2] = axis.z;
  }
  py::dict d;
  d["mass"] = mp.mass;
  d["volume"] = mp.volume;
  d["centre_of_mass"] = vec3_array(mp.centre_of_mass);
  d["inertia"] = inertia;
  d["principal_moments"] = vec3_array(mp.principal_moments);
  d["principal_axes"] = axes;
  return d;
}

}  // namespace hedge::python
