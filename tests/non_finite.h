// Test support: a mesh with one position that is not finite, and the check that a whole-mesh call
// refuses it by name and leaves the mesh as it was.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "hedge/core/surface_mesh.h"
#include "hedge/error.h"

namespace hedge::test {

//! Sets v's y to NaN through position(), which checks nothing (as a write through a binding's view).
inline void poison(SurfaceMesh& m, Vertex v) { m.position(v).y = std::numeric_limits<float>::quiet_NaN(); }

//! f() must throw InvalidInputError saying "WHAT: vertex V has a non-finite position (x, nan, z)"
//! and change neither the elements nor any position (compared bit for bit, NaN included). Then v's
//! position is restored and the mesh must be valid.
template <typename F>
void expect_refuses_non_finite(SurfaceMesh& m, Vertex v, const std::string& what, F&& f) {
  const Vec3 good = m.position(v);
  poison(m, v);
  const std::size_t nv = m.vertex_slots(), ne = m.edge_slots(), nf = m.face_slots();
  const std::vector<Vec3> before = m.positions().vector();
  std::string message;
  try {
    f();
    ADD_FAILURE() << what << ": a NaN position was accepted";
  } catch (const InvalidInputError& e) {
    message = e.what();
  }
  EXPECT_EQ(message.rfind(what + ": vertex " + std::to_string(v.idx()) + " has a non-finite position (", 0),
            0u)
      << message;
  EXPECT_NE(message.find("nan"), std::string::npos) << message;
  EXPECT_EQ(m.vertex_slots(), nv);
  EXPECT_EQ(m.edge_slots(), ne);
  EXPECT_EQ(m.face_slots(), nf);
  ASSERT_EQ(m.positions().vector().size(), before.size());
  EXPECT_EQ(std::memcmp(m.positions().vector().data(), before.data(), before.size() * sizeof(Vec3)), 0)
      << what << " moved a vertex before refusing";
  m.position(v) = good;
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
}

}  // namespace hedge::test
