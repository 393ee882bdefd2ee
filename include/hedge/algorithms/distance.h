// How far apart two surfaces are: the sampled one-sided and symmetric Hausdorff distances and the
// mean distance, as used to judge a simplified mesh against its original.
//
// The points of a surface are sampled: every vertex that has a face, plus `samples` points drawn
// on its faces with probability proportional to area (a face of several corners through its fan
// triangles (c0, c[i], c[i+1]), as in locate.h). The draws are a seeded, stratified sequence, so the
// same meshes, sample count and seed give the same points, whatever the number of threads. Each
// point's distance to the other surface is exact (FaceBvh::closest_point, in double); the
// maximum over a finite sample is a lower bound of the true Hausdorff distance, which it
// approaches as the sample grows (a sample misses at most what lies between its points).
//
// Threads: both functions split the points between up to min(options.threads, max_threads())
// threads (core/threads.h), the calling thread one of them, and join them before they return.
// Concurrent calls may share the meshes, which they only read.
#pragma once

#include <cstddef>
#include <cstdint>

#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"

namespace hedge {

//! Most face samples a call draws on each surface: 10^8, which takes 800 MB for the distances
//! (8 bytes a point, one surface at a time) and a minute or two of queries.
inline constexpr std::size_t kMaxDistanceSamples = 100'000'000;

struct DistanceOptions {
  //! Points drawn on the faces of each surface, besides its vertices. 0: vertices only; at most
  //! kMaxDistanceSamples.
  std::size_t samples = 100000;
  //! Seed of the draws.
  std::uint64_t seed = 1;
  //! Most threads measuring the points (1 or more; each takes an equal share), the calling thread
  //! included; the process-wide max_threads() (core/threads.h) caps it too. The results do not
  //! depend on it.
  unsigned threads = 2;
};

//! Distances of the sampled points of one surface to another surface.
struct OneSidedDistance {
  //! The largest distance of a sampled point to the other surface.
  double max = 0;
  //! The mean distance over the sampled points.
  double mean = 0;
  //! The sampled point that is farthest from the other surface.
  Vec3 farthest{0, 0, 0};
  //! Number of sampled points (vertices plus face samples).
  std::size_t points = 0;
};

struct HausdorffDistance {
  //! The symmetric (sampled) Hausdorff distance: the larger of the two one-sided maxima.
  double distance = 0;
  //! The mean distance over the sampled points of both surfaces together.
  double mean = 0;
  //! Points of a measured against surface b, and the other way.
  OneSidedDistance a_to_b, b_to_a;
};

//! The distances of the sampled points of `from` (see the file comment) to the surface `to`.
//! Cost: a FaceBvh over `to`, O(F log F), then one closest-point query per point, O(log F)
//! expected each: O((V + samples) log F) in all, shared among options.threads threads. Memory:
//! 8 bytes per point (V + samples) besides the FaceBvh.
//! \throw InvalidInputError, naming the mesh, if either mesh has no face, if a position of either
//!   mesh is not finite (the vertex is named), if options.threads is 0, or if options.samples is
//!   more than kMaxDistanceSamples (checked first, before any work).
OneSidedDistance one_sided_distance(const SurfaceMesh& from, const SurfaceMesh& to,
                                    const DistanceOptions& options = {});

//! The symmetric sampled Hausdorff distance between a and b and the mean distance: both one-sided
//! measures, each surface sampled with the same options. Twice the cost of one_sided_distance.
//! \throw InvalidInputError as one_sided_distance.
HausdorffDistance hausdorff_distance(const SurfaceMesh& a, const SurfaceMesh& b,
                                     const DistanceOptions& options = {});

}  // namespace hedge
