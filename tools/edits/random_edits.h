// The seeded random-operation driver: random sequences of local operations, behind the stress
// tests and the `hedge stress` and `hedge render-buffers` commands. Tool code, not part of the
// library's API.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "hedge/core/surface_mesh.h"

namespace hedge {

enum class EditKind : int {
  split_edge,
  collapse,
  flip,
  split_face,
  cut_face,       //!< cut_face(h0, h1) on a polygon
  remove_face,    //!< remove_face, then add_face with the same corners when possible
  remove_vertex,  //!< remove_vertex, then fill_hole on the hole it leaves
  count
};
inline constexpr std::size_t kEditKinds = static_cast<std::size_t>(EditKind::count);
const char* edit_name(EditKind k);

struct RandomEditOptions {
  std::uint64_t seed = 1;
  std::size_t operations = 1000;
  //! Run validate() after every n-th operation (1: after each); 0 validates only at the end.
  std::size_t validate_every = 0;
  //! Compact with garbage_collection() after every n-th operation; 0 never.
  std::size_t collect_every = 5000;
};

struct RandomEditReport {
  std::array<std::size_t, kEditKinds> applied{};
  std::array<std::size_t, kEditKinds> refused{};
  //! Operations after which V - E + F differed from what the operation predicts.
  std::size_t euler_mismatches = 0;
  //! False if any validation failed; problems holds the first failing report.
  bool valid = true;
  std::size_t first_invalid_operation = 0;
  EditKind first_invalid_kind = EditKind::count;  //!< the operation after which validation failed
  std::vector<std::string> problems;
  std::size_t total_applied() const;
  std::size_t total_refused() const;
};

//! Random operations on one mesh, one per step(), from one seeded generator: the same seed gives
//! the same sequence on every platform. Each pick goes to the operation, whose own check may refuse
//! it (a refused operation leaves the mesh unchanged). The mesh size is kept within a factor of four
//! of its size at construction by steering between splits and collapses.
class RandomEditor {
 public:
  RandomEditor(SurfaceMesh& mesh, std::uint64_t seed);

  struct Step {
    EditKind kind = EditKind::count;
    bool applied = false;
    //! False if the operation was applied and V - E + F differs from what it predicts.
    bool euler_kept = true;
  };
  //! One random operation. O(valence) (a face removal and re-adding: O(face degree x valence)).
  Step step();

 private:
  SurfaceMesh* mesh_;
  std::mt19937_64 rng_;
  std::size_t start_faces_;
};

//! Applies `options.operations` steps of a RandomEditor seeded with `options.seed`, counting what
//! was applied and refused, collecting garbage and validating as the options say, and validating
//! once at the end. Stops early when validation fails. O(operations x valence), plus O(n) per
//! validation.
RandomEditReport random_edits(SurfaceMesh& mesh, const RandomEditOptions& options);

}  // namespace hedge
