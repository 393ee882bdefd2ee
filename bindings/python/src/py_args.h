// Arguments as Python gives them, converted with a clear error naming the call and the argument:
// points (any sequence or array of 3 numbers) and paths (str or os.PathLike); and results as
// Python takes them: points as (3,) arrays, mass properties as a dict.
#pragma once

#include <string>

#include "hedge/algorithms/mass_properties.h"
#include "hedge/core/vec.h"
#include "py_support.h"

namespace hedge::python {

//! `p` as 3 finite coordinates in double. \throw BindingError (HEDGE_ERROR_INVALID_ARGUMENT) "CALL:
//! WHAT must be 3 numbers x, y, z, got ..." for another shape or type, "CALL: WHAT (x, y, z) is not
//! finite" for a coordinate that is not.
Vec3d point3d(const py::handle& p, const char* call, const char* what);
//! point3d() as the library's float point (a coordinate beyond float's range is not finite).
Vec3 point3(const py::handle& p, const char* call, const char* what);

//! A path given as str or os.PathLike (pathlib.Path), as the file functions of Python take it
//! (py_mesh.cpp). \throw InvalidInputError for bytes.
std::string fspath(const py::object& path);

//! A point as a fresh (3,) float64 array.
py::array_t<double> vec3_array(const Vec3d& v);
py::array_t<double> vec3_array(const Vec3& v);
//! Mass properties as a dict: mass, volume, centre_of_mass (3,), inertia (3, 3) about the centre of
//! mass, principal_moments (3,), principal_axes (3, 3), one unit axis a row.
py::dict mass_properties_dict(const MassProperties& mp);

}  // namespace hedge::python
