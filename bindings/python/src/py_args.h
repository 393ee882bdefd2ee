// Arguments as Python gives them, converted with a clear error naming the call and the argument:
// points (any sequence or array of 3 numbers) and paths (str or os.PathLike).
#pragma once

#include <string>

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

}  // namespace hedge::python
