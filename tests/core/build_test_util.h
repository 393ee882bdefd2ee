// Helpers shared by the tests of build() and of its steps (tests/core/build*_test.cpp).
#pragma once

#include "hedge/core/build.h"
#include "hedge/core/surface_mesh.h"

namespace hedge::test {

//! Build options with the repair policy.
inline BuildOptions repair() {
  BuildOptions o;
  o.policy = TopologyPolicy::repair;
  return o;
}

//! The Euler characteristic V - E + F of the live elements.
inline long long euler(const SurfaceMesh& m) {
  return static_cast<long long>(m.n_vertices()) - static_cast<long long>(m.n_edges()) +
         static_cast<long long>(m.n_faces());
}

}  // namespace hedge::test
