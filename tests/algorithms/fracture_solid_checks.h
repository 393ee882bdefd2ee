// Checks shared by the solid fracture tests: every piece and the remaining object closed, valid,
// outward and of positive volume, and the volume conserved.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hedge/algorithms/fracture_solid.h"
#include "hedge/algorithms/geometry.h"

namespace hedge::solid_test {

inline bool closed(const SurfaceMesh& m) {
  for (Halfedge h : m.halfedges())
    if (m.is_boundary(h)) return false;
  return true;
}

//! Closed, valid, triangles, positive volume: "" or what is wrong.
inline std::string solid_problem(const SurfaceMesh& m) {
  const auto problems = m.validate();
  if (!problems.empty()) return "invalid: " + problems.front();
  if (!closed(m)) return "open";
  if (!(volume(m) > 0)) return "volume " + std::to_string(volume(m));
  return "";
}

//! The pieces and the remaining object are solids whose volumes add up to `before` (1e-6
//! relative); caps are marked inner and the bonds name existing pieces.
inline void expect_solid_strike(const SurfaceMesh& remaining, const SolidFractureResult& r, double before,
                                double relative = 1e-6) {
  // The remaining object is empty when the region took all of it.
  double total = remaining.n_faces() ? volume(remaining) : 0.0;
  if (remaining.n_faces()) EXPECT_EQ(solid_problem(remaining), "") << "the remaining object";
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    const SolidPiece& p = r.pieces[i];
    EXPECT_EQ(solid_problem(p.mesh), "") << "piece " << i;
    EXPECT_GT(p.volume, 0) << "piece " << i;
    EXPECT_NEAR(p.volume, volume(p.mesh), 1e-9 * std::abs(before));
    EXPECT_GT(p.mass.mass, 0);
    total += volume(p.mesh);
    const FaceProperty<std::uint8_t> inner = p.mesh.get_face_property<std::uint8_t>(kInnerProperty);
    ASSERT_TRUE(inner) << "piece " << i;
    double caps = 0;
    for (Face f : p.mesh.faces())
      if (inner[f]) caps += face_area(p.mesh, f);
    // cap_area is summed in double before the positions are rounded to float.
    EXPECT_NEAR(caps, p.cap_area, 1e-5 * p.cap_area + 1e-8 * std::pow(std::abs(before), 2.0 / 3))
        << "piece " << i;
  }
  EXPECT_NEAR(total, before, relative * std::abs(before));
  for (const SolidBond& b : r.bonds) {
    EXPECT_LT(b.a, r.pieces.size());
    EXPECT_TRUE(b.b == kSolidRemaining || (b.b < r.pieces.size() && b.a < b.b));
    EXPECT_GT(b.area, 0);
  }
}

}  // namespace hedge::solid_test
