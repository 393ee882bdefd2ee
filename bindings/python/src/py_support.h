// The Python binding's shared machinery: the mesh object, the error mapping and the guard of the
// numpy views. The binding sits on the binding core (src/binding/), as the C ABI and the
// WebAssembly module do: handle checks, error kinds, refusals and the busy check are the core's.
//
// Errors. Every bound function lets the core's and the library's exceptions propagate; the
// translator installed by register_errors() turns each into the hedge._errors class of its kind
// (binding::kind_name), with the message and the refusal. A refused edit does not raise: the
// edits catch the refusal themselves (py_edits.cpp).
//
// Views. mesh.positions and the connectivity views are numpy arrays over the mesh's own vectors.
// Each view's base is a ViewOwner, which keeps the mesh state alive and counts as an exported view.
// An edit that adds elements may move those vectors, so it is refused while any view is alive
// (require_no_views(), hedge.ViewsExportedError), as bytearray refuses to resize under a memoryview.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>

#include "binding/mesh_state.h"
#include "hedge/core/build.h"

namespace hedge::python {

namespace py = pybind11;

//! What a Python Mesh holds: the binding core's state, the build report, and the count of numpy
//! views alive. `views` is touched with the GIL held only.
struct State : binding::MeshState {
  BuildReport report;
  int views = 0;
  //! The reason of the last refused edit on this mesh ("" if the last edit was allowed).
  std::string last_refusal;
};

//! The Python Mesh: a handle to its state, shared with the views' owners.
class Mesh {
 public:
  Mesh() : s_(std::make_shared<State>()) {}
  explicit Mesh(std::shared_ptr<State> state) : s_(std::move(state)) {}
  const std::shared_ptr<State>& state() const { return s_; }
  //! The mesh for this call. \throw BindingError (HEDGE_ERROR_BUSY) if another thread uses it.
  binding::MeshUse<State> use() const { return binding::MeshUse<State>(s_); }

 private:
  std::shared_ptr<State> s_;
};

//! Thrown by require_no_views(); raised as hedge.ViewsExportedError.
struct ViewsExported {
  std::string message;
};

//! \throw ViewsExported if numpy views of the mesh's arrays are alive; `what` names the call.
void require_no_views(const State& state, const std::string& what);

//! A Python int as an element index of the core's checks: a negative one (or one past 32 bits) is
//! out of range. \throw BindingError (HEDGE_ERROR_BAD_HANDLE) "<kind> -1 is out of range".
std::uint32_t element_index(std::int64_t i, const char* kind);

//! Installs the translator of hedge's exceptions into the hedge._errors classes.
void register_errors();

//! Mesh construction, files, arrays, counts and validate (py_mesh.cpp).
void bind_mesh(py::module_& m, py::class_<Mesh>& mesh);
//! The numpy views and positions_changed (py_views.cpp).
void bind_views(py::module_& m, py::class_<Mesh>& mesh);
//! The edits and their can_* predicates (py_edits.cpp).
void bind_edits(py::class_<Mesh>& mesh);
//! The scalar queries of one element and the one-ring (py_queries.cpp).
void bind_queries(py::class_<Mesh>& mesh);
//! ray_cast and closest_point over arrays (py_picking.cpp).
void bind_picking(py::class_<Mesh>& mesh);
//! hedge.render() and Mesh._repr_png_ (py_render.cpp).
void bind_render(py::module_& m, py::class_<Mesh>& mesh);
//! Mesh.fracture and hedge.Shard (py_fracture.cpp).
void bind_fracture(py::module_& m, py::class_<Mesh>& mesh);
//! Mesh.fracture_solid, Mesh.solid_fracture_refusal and hedge.Piece (py_fracture_solid.cpp).
void bind_fracture_solid(py::module_& m, py::class_<Mesh>& mesh);
//! The whole-mesh algorithms and hedge.hausdorff_distance (py_algorithms.cpp).
void bind_algorithms(py::class_<Mesh>& mesh, py::module_& m);

}  // namespace hedge::python
