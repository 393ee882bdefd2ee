// The strong guarantee for whole-mesh algorithms that do not give it themselves: run the algorithm
// on the mesh, and if it throws, put the mesh back as it was before rethrowing.
//
// Used where an algorithm rewrites the whole mesh in place and can fail halfway, which would leave
// a partial result: decimate() (a run of collapses cut short by an allocation failure),
// garbage_collection() and reorder() (compacted arrays next to ones not yet compacted). Algorithms
// that give the guarantee themselves (subdivide, smooth) need no copy. Costs one copy of the mesh,
// small next to what those algorithms allocate.
#pragma once

#include <utility>

#include "hedge/core/surface_mesh.h"

namespace hedge::binding {

//! Runs body() (which may change `mesh`) and returns its result; if body() throws, `mesh` is
//! restored to a copy taken before, then the exception propagates. The copy is taken first, so
//! running out of memory for it throws before anything changed. The restore is a move (noexcept);
//! the change log records a reset for its consumers, which rebuild.
template <typename Body>
auto with_rollback(SurfaceMesh& mesh, Body&& body) -> decltype(body()) {
  SurfaceMesh backup = mesh;
  try {
    return body();
  } catch (...) {
    mesh = std::move(backup);
    throw;
  }
}

}  // namespace hedge::binding
