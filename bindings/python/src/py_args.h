// Arguments as Python gives them, converted with a clear error naming the call and the argument:
// points (any sequence or array of 3 numbers) and paths (str or os.PathLike); and results as
// Python takes them: points as (3,) arrays, mass properties as a dict.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hedge/algorithms/convex_hull.h"
#include "hedge/algorithms/fracture.h"
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

//! An argument of element indices, as numpy users give them: a 1-D array or sequence of integers,
//! or, if `slots` is given, a bool mask of exactly that many entries, which stands for the indices of
//! its True entries (np.flatnonzero). The indices are not range-checked here (element_index() and
//! the core's handle checks do it). \throw BindingError (HEDGE_ERROR_INVALID_ARGUMENT) "CALL: WHAT
//! must ..." for floats, strings, objects, more than one dimension or a mask of another length.
std::vector<std::int64_t> index_list(const py::handle& x, const char* call, const char* what,
                                     std::optional<std::size_t> slots = std::nullopt);
//! `x` as a C-contiguous int64 array of any shape, for the callers that want rows (from_arrays' F);
//! null if numpy cannot make one rectangular array of it (a ragged list).
//! \throw BindingError (HEDGE_ERROR_INVALID_ARGUMENT) "CALL: WHAT must hold integers, not ..." for
//! an array of another kind (floats, bools, strings).
py::array_t<std::int64_t, py::array::c_style> integer_array(const py::handle& x, const char* call,
                                                            const char* what);
//! A mask of one entry per slot: any 1-D numeric or bool array of `slots` entries; nonzero entries
//! are chosen (1), zeros not (0). \throw BindingError (HEDGE_ERROR_INVALID_ARGUMENT) otherwise.
std::vector<std::uint8_t> slot_mask(const py::handle& x, std::size_t slots, const char* call,
                                    const char* what);

//! A path given as str or os.PathLike (pathlib.Path), as the file functions of Python take it
//! (py_mesh.cpp). \throw InvalidInputError for bytes.
std::string fspath(const py::object& path);

//! A point as a fresh (3,) float64 array.
py::array_t<double> vec3_array(const Vec3d& v);
py::array_t<double> vec3_array(const Vec3& v);
//! Mass properties as a dict: mass, volume, centre_of_mass (3,), inertia (3, 3) about the centre of
//! mass, principal_moments (3,), principal_axes (3, 3), one unit axis a row.
py::dict mass_properties_dict(const MassProperties& mp);

//! What a convex hull's points span, as Python names it: 'empty', 'point', 'segment', 'flat' or 'solid'.
const char* hull_dimension_name(HullDimension d);
//! A fracture material: a preset's name, or a dict in the schema of the CLI's material files
//! (docs/fracture.md), parsed by the same parser (py_fracture.cpp). \throw InvalidInputError "CALL:
//! material ..." for another type, an unknown preset or a bad field.
FractureMaterial fracture_material_arg(const py::object& material, const std::string& call);
//! A fracture's seed: any Python integer in [0, 2^64) (numpy's too), not a bool or a float.
//! \throw InvalidInputError "CALL: seed must be a whole number in [0, 2^64) ..." otherwise.
std::uint64_t seed_arg(const py::object& seed, const std::string& call);

}  // namespace hedge::python
