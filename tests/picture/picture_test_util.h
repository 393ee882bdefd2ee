// Small scenes for the picture tests: meshes built from arrays and an orthographic camera that maps
// world [-1, 1] x [-1, 1] onto the whole picture, so that expected pixels can be computed by hand.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hedge/core/build.h"
#include "picture/camera.h"

namespace hedge::picture::test {

inline SurfaceMesh mesh_of(std::vector<Vec3> positions, std::vector<std::uint32_t> indices,
                           std::vector<std::uint32_t> face_sizes = {}) {
  IndexedMesh in;
  in.positions = std::move(positions);
  in.indices = std::move(indices);
  in.face_sizes = std::move(face_sizes);
  return build(in);
}

//! How often `what` occurs in `text`.
inline std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

//! Looks down -z from z = 10; world (x, y) lands at pixel ((x + 1) / 2 * width, (1 - y) / 2 * height)
//! for a square picture.
inline Camera ortho_camera() {
  Camera c;
  c.eye = {0, 0, 10};
  c.target = {0, 0, 0};
  c.up = {0, 1, 0};
  c.fov_degrees = 0;
  c.ortho_height = 2;
  return c;
}

}  // namespace hedge::picture::test
