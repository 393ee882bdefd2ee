// Progress of a long algorithm (subdivision, decimation, ...), for a progress bar.
//
// An algorithm that takes a Progress calls it from the calling thread with the fraction of its work
// done, rising from 0 to 1, a few hundred times at most over the whole run (so the cost of the call
// does not matter). An empty Progress is never called. The callback must not touch the mesh being
// worked on; it may throw to abandon the work, and the algorithm then leaves the mesh as its own
// header says for an error.
#pragma once

#include <functional>

namespace hedge {

using Progress = std::function<void(double fraction_done)>;

//! Calls `progress` (if set) with `fraction`, clamped to [0, 1].
inline void report_progress(const Progress& progress, double fraction) {
  if (progress) progress(fraction < 0 ? 0.0 : fraction > 1 ? 1.0 : fraction);
}

}  // namespace hedge
