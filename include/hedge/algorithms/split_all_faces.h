// Splitting every face of a mesh at its centroid, in one pass.
#pragma once

#include <vector>

#include "hedge/core/surface_mesh.h"

namespace hedge {

//! Splits every live face at its centroid. \return the new vertices. O(n).
std::vector<Vertex> split_all_faces(SurfaceMesh& mesh);

}  // namespace hedge
