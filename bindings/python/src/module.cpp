// hedge._hedge: the native half of the Python package `hedge` (bindings/python/hedge/). The pieces
// are bound in py_mesh.cpp, py_views.cpp, py_edits.cpp,
// py_queries.cpp, py_picking.cpp, py_algorithms.cpp, py_render.cpp, py_fracture.cpp and
// py_fracture_solid.cpp; py_support.h describes the whole.
#include "py_support.h"

PYBIND11_MODULE(_hedge, m) {
  using namespace hedge::python;
  m.doc() = "hedge's native module: half-edge meshes with numpy views. Import `hedge`, not this.";
  register_errors();
  py::class_<Mesh> mesh(m, "Mesh",
                        "A polygon half-edge mesh. Build it with Mesh.from_arrays() or hedge.read(). "
                        "A mesh takes calls from one thread at a time (BusyError otherwise).");
  bind_mesh(m, mesh);
  bind_views(m, mesh);
  bind_edits(mesh);
  bind_queries(mesh);
  bind_picking(mesh);
  bind_render(m, mesh);
  bind_fracture(m, mesh);
  bind_fracture_solid(m, mesh);
  bind_algorithms(mesh, m);
}
