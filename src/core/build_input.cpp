// build(), first steps: checks of the input, welding, and, when the caller's triangles cannot be
// used in place, a copy of the faces without repeated corners or degenerate faces.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "build_internal.h"
#include "hedge/error.h"

namespace hedge {

using build_detail::kMaxNamed;
using build_detail::list_str;

void MeshBuilder::check_input() const {
  const std::size_t nv = in_.positions.size();
  if (nv >= kInvalidIndex) throw InvalidInputError("too many vertices for 32-bit indices");
  // The scans below test whole blocks without branching (so that they vectorise) and look for the
  // first offending element only in a block that has one.
  constexpr std::size_t kBlock = 1024;
  constexpr auto kMaxCoordinate = std::numeric_limits<decltype(Vec3::x)>::max();  // NaN compares false
  for (std::size_t b = 0; b < nv; b += kBlock) {
    const std::size_t e = std::min(nv, b + kBlock);
    bool finite = true;
    for (std::size_t i = b; i < e; ++i) {
      const Vec3& p = in_.positions[i];
      finite &= (int(std::fabs(p.x) <= kMaxCoordinate) & int(std::fabs(p.y) <= kMaxCoordinate) &
                 int(std::fabs(p.z) <= kMaxCoordinate)) != 0;
    }
    if (finite) continue;
    for (std::size_t i = b; i < e; ++i)
      if (!is_finite(in_.positions[i]))
        throw InvalidInputError("vertex " + std::to_string(i) + " has a non-finite coordinate");
  }
  if (in_.face_sizes.empty()) {
    if (in_.indices.size() % 3 != 0)
      throw InvalidInputError("triangle index count " + std::to_string(in_.indices.size()) +
                              " is not a multiple of 3");
  } else {
    std::size_t sum = 0;
    for (auto s : in_.face_sizes) sum += s;
    if (sum != in_.indices.size())
      throw InvalidInputError("face sizes add up to " + std::to_string(sum) + " corners but there are " +
                              std::to_string(in_.indices.size()) + " indices");
  }
  if (in_.indices.size() >= kInvalidIndex / 2) throw InvalidInputError("too many corners for 32-bit indices");
  const std::size_t ni = in_.indices.size();
  const Index* corner_vertex = in_.indices.data();
  const Index n_vert = static_cast<Index>(nv);  // 32-bit compares vectorise
  for (std::size_t b = 0; b < ni; b += kBlock) {
    const std::size_t e = std::min(ni, b + kBlock);
    Index out_of_range = 0;
    for (std::size_t c = b; c < e; ++c) out_of_range |= Index(corner_vertex[c] >= n_vert);
    if (!out_of_range) continue;
    for (std::size_t c = b; c < e; ++c)
      if (corner_vertex[c] >= nv)
        throw InvalidInputError("corner " + std::to_string(c) + " refers to vertex " +
                                std::to_string(corner_vertex[c]) + " but there are " + std::to_string(nv) +
                                " vertices");
  }
  auto check_pool = [&](std::span<const Index> idx, std::size_t pool, const char* what) {
    if (idx.empty()) return;
    if (idx.size() != in_.indices.size())
      throw InvalidInputError(std::string(what) + " index count differs from the corner count");
    for (std::size_t c = 0; c < idx.size(); ++c)
      if (idx[c] >= pool)
        throw InvalidInputError("corner " + std::to_string(c) + " refers to " + what + " " +
                                std::to_string(idx[c]) + " but there are " + std::to_string(pool));
  };
  check_pool(in_.texcoord_indices, in_.texcoords.size(), "texcoord");
  check_pool(in_.normal_indices, in_.normals.size(), "normal");
  check_pool(in_.color_indices, in_.colors.size(), "color");
  for (std::size_t i = 0; i < in_.colors.size(); ++i) {
    const Color& k = in_.colors[i];
    if (!std::isfinite(k.r) || !std::isfinite(k.g) || !std::isfinite(k.b) || !std::isfinite(k.a))
      throw InvalidInputError("color " + std::to_string(i) + " has a non-finite component");
  }
}

void MeshBuilder::weld() {
  if (opt_.weld == Weld::none) return;  // positions_ stays empty: the input's are used
  weld_map_ = weld_positions(in_.positions, opt_.weld, opt_.weld_epsilon, positions_);
  rep_.welded_vertices = in_.positions.size() - positions_.size();
  weld_first_.assign(positions_.size(), kInvalidIndex);
  for (Index i = static_cast<Index>(weld_map_.size()); i-- > 0;) weld_first_[weld_map_[i]] = i;
}

bool MeshBuilder::clean_faces() {
  f_.n_faces = static_cast<Index>(in_.face_count());
  if (in_.face_sizes.empty() && weld_map_.empty()) {
    // Fast path: the caller's triangles, used in place. pair_fast() checks for degenerate ones on
    // the way; triangles_are_clean() does when it cannot.
    f_.corners = in_.indices;
    return true;
  }
  clean_faces_general();
  return false;
}

void MeshBuilder::clean_faces_general() {
  const bool tri = in_.face_sizes.empty();
  const std::size_t nf = in_.face_count();
  auto vert = [&](std::size_t c) { return weld_map_.empty() ? in_.indices[c] : weld_map_[in_.indices[c]]; };

  f_.own_corners.clear();
  f_.own_corners.reserve(in_.indices.size());
  f_.start.assign(1, 0);
  f_.start.reserve(nf + 1);
  f_.face_origin.clear();
  f_.corner_origin.clear();
  f_.corner_origin.reserve(in_.indices.size());
  std::vector<std::string> named;
  std::size_t bad = 0;
  std::vector<Index> face, origin;  // scratch for one polygon

  std::size_t c0 = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    const std::size_t n = tri ? 3 : in_.face_sizes[f];
    face.clear();
    origin.clear();
    for (std::size_t k = 0; k < n; ++k) {
      Index v = vert(c0 + k);
      if (!face.empty() && face.back() == v) continue;  // consecutive repeat
      face.push_back(v);
      origin.push_back(static_cast<Index>(c0 + k));
    }
    while (face.size() > 1 && face.front() == face.back()) {
      face.pop_back();
      origin.pop_back();
    }
    const std::size_t repeated = n - face.size();
    bool degenerate = face.size() < 3;
    if (!degenerate) {
      // Any other repeat pinches the face into two loops: it has no disk to fill.
      if (face.size() <= 16) {
        for (std::size_t i = 0; i < face.size() && !degenerate; ++i)
          for (std::size_t j = i + 1; j < face.size() && !degenerate; ++j) degenerate = face[i] == face[j];
      } else {
        std::vector<Index> sorted = face;
        std::sort(sorted.begin(), sorted.end());
        degenerate = std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
      }
    }
    if ((degenerate || repeated > 0) && opt_.policy == TopologyPolicy::strict) {
      ++bad;
      if (named.size() < kMaxNamed)
        named.push_back("face " + std::to_string(f) + " repeats a vertex or has fewer than 3 corners");
    }
    if (degenerate) {
      ++rep_.degenerate_faces;
    } else {
      rep_.repeated_corners += repeated;
      f_.own_corners.insert(f_.own_corners.end(), face.begin(), face.end());
      f_.corner_origin.insert(f_.corner_origin.end(), origin.begin(), origin.end());
      f_.face_origin.push_back(static_cast<Index>(f));
      f_.start.push_back(static_cast<Index>(f_.own_corners.size()));
    }
    c0 += n;
  }
  if (bad > 0) throw TopologyError("degenerate faces: " + list_str(named, bad));
  f_.corners = f_.own_corners;
  f_.n_faces = static_cast<Index>(f_.start.size() - 1);
}

}  // namespace hedge
