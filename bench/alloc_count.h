// Heap accounting for the peers binary: alloc_count.cpp replaces the global operator new and
// delete with versions that, while counting is on, add and subtract malloc_usable_size() of every
// block. Counting is off outside measurements, so timed code pays only an untaken branch.
// Single-threaded use only (the measured builds run on one thread).
#pragma once

#include <cstddef>
#include <cstdint>

namespace bench::alloc {

struct Stats {
  std::int64_t live = 0;         //!< net bytes allocated and not freed since start()
  std::int64_t peak = 0;         //!< highest `live` seen since start()
  std::int64_t allocations = 0;  //!< number of operator new calls since start()
};

void start();
Stats stop();

}  // namespace bench::alloc
