// Arguments as Python gives them and results as Python takes them, shared by the binding's files
// (py_args.h).
#include "py_args.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

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

namespace {

[[noreturn]] void bad_argument(const char* call, const char* what, const std::string& text) {
  binding::fail(HEDGE_ERROR_INVALID_ARGUMENT, std::string(call) + ": " + what + " " + text);
}

//! `x` as numpy sees it (np.asarray), or none if numpy cannot make an array of it (a ragged list).
//! Strings and bytes are refused: numpy would take them as 0-D arrays of characters.
py::object as_numpy(const py::handle& x, const char* call, const char* what, const char* wanted) {
  if (py::isinstance<py::str>(x) || py::isinstance<py::bytes>(x))
    bad_argument(call, what, std::string("must be ") + wanted + ", not a string");
  try {
    return py::module_::import("numpy").attr("asarray")(x);
  } catch (const py::error_already_set& e) {
    if (!e.matches(PyExc_ValueError) && !e.matches(PyExc_TypeError)) throw;
    return py::none();
  }
}

std::string dtype_text(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

//! An integer array (of any integer dtype) as int64, saturating the uint64 values past int64's
//! range so that they stay out of range instead of turning negative.
py::array_t<std::int64_t, py::array::c_style> to_int64(const py::array& a) {
  if (a.dtype().kind() == 'u' && a.dtype().itemsize() == 8) {
    const auto u = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    py::array_t<std::int64_t, py::array::c_style> out(
        std::vector<py::ssize_t>(u.shape(), u.shape() + u.ndim()));
    for (py::ssize_t i = 0; i < u.size(); ++i)
      out.mutable_data()[i] = u.data()[i] > 0x7fffffffffffffffull ? INT64_MAX : std::int64_t(u.data()[i]);
    return out;
  }
  return py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
}

}  // namespace

py::array_t<std::int64_t, py::array::c_style> integer_array(const py::handle& x, const char* call,
                                                            const char* what) {
  const py::object o = as_numpy(x, call, what, "an array of integers");
  if (o.is_none()) return {};
  const auto a = py::reinterpret_borrow<py::array>(o);
  const char kind = a.dtype().kind();
  // An older numpy makes a ragged list an array of objects rather than refusing it.
  if (kind == 'O' && !py::isinstance<py::array>(x)) return {};
  // An empty list has numpy's default dtype, float64: it holds no float all the same.
  const bool empty_list = a.size() == 0 && !py::isinstance<py::array>(x);
  if (kind != 'i' && kind != 'u' && !empty_list)
    bad_argument(call, what, "must hold integers, not " + dtype_text(a));
  return to_int64(a);
}

std::vector<std::int64_t> index_list(const py::handle& x, const char* call, const char* what,
                                     std::optional<std::size_t> slots) {
  const py::object o = as_numpy(x, call, what, "a 1-D array of integer indices");
  if (o.is_none()) bad_argument(call, what, "must be a 1-D array of integer indices");
  const auto a = py::reinterpret_borrow<py::array>(o);
  if (a.ndim() != 1)
    bad_argument(
        call, what,
        "must be a 1-D array of integer indices, not of " + std::to_string(a.ndim()) + " dimensions");
  std::vector<std::int64_t> out;
  if (a.dtype().kind() == 'b') {
    const auto n = static_cast<std::size_t>(a.shape(0));
    if (!slots) bad_argument(call, what, "must hold integer indices, not bool");
    if (n != *slots)
      bad_argument(call, what,
                   "as a bool mask must have one entry per slot (" + std::to_string(*slots) + "), not " +
                       std::to_string(n));
    const auto b = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(a);
    for (std::size_t i = 0; i < n; ++i)
      if (b.data()[i]) out.push_back(static_cast<std::int64_t>(i));
    return out;
  }
  const auto i64 =
      integer_array(a.size() == 0 && !py::isinstance<py::array>(x) ? x : py::handle(a), call, what);
  out.assign(i64.data(), i64.data() + i64.size());
  return out;
}

std::vector<std::uint8_t> slot_mask(const py::handle& x, std::size_t slots, const char* call,
                                    const char* what) {
  const py::object o = as_numpy(x, call, what, "a 1-D array of numbers or bools");
  const char kind = o.is_none() ? 'O' : py::reinterpret_borrow<py::array>(o).dtype().kind();
  if (kind != 'b' && kind != 'i' && kind != 'u' && kind != 'f')
    bad_argument(call, what, "must be a 1-D array of numbers or bools, one entry per slot");
  const auto a = py::reinterpret_borrow<py::array>(o);
  if (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != slots)
    bad_argument(call, what,
                 "must have one entry per slot (" + std::to_string(slots) + "), not shape " +
                     py::str(a.attr("shape")).cast<std::string>());
  // Nonzero as numpy has it: NaN counts as nonzero, -0.0 does not.
  const auto nonzero =
      py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(a.attr("astype")("bool"));
  return std::vector<std::uint8_t>(nonzero.data(), nonzero.data() + nonzero.size());
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
