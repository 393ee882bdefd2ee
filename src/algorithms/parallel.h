// Splitting a loop over element indices between the cores, for the algorithms whose passes write
// disjoint elements (subdivision builds every element from a formula of the old ones).
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

#if defined(__linux__)
#include <sched.h>
#endif

namespace hedge::detail {

//! The cores this process may run on (its affinity mask on Linux), at least 1.
inline unsigned usable_cores() {
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
  return 1;
#elif defined(__linux__)
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return unsigned(std::max(1, CPU_COUNT(&set)));
  return std::max(1u, std::thread::hardware_concurrency());
#else
  return std::max(1u, std::thread::hardware_concurrency());
#endif
}

//! Calls body(begin, end) on consecutive ranges covering [0, n), one per usable core (at most 8),
//! each on its own thread but the first, which runs on the calling thread. Below `grain` elements
//! per range it stays on the calling thread: a thread costs some tens of microseconds. The body
//! must write only what its range owns and must not throw.
template <typename Body>
void parallel_ranges(std::size_t n, Body&& body, std::size_t grain = 1u << 15) {
  const std::size_t parts = std::min<std::size_t>({usable_cores(), 8, std::max<std::size_t>(1, n / grain)});
  if (parts <= 1) {
    body(std::size_t(0), n);
    return;
  }
  std::vector<std::thread> threads;
  threads.reserve(parts - 1);
  std::size_t p = 1;
  try {
    for (; p < parts; ++p)
      threads.emplace_back([&body, n, p, parts] { body(n * p / parts, n * (p + 1) / parts); });
  } catch (...) {
    // No thread to be had (a platform without them, or out of resources): the rest runs here.
  }
  body(std::size_t(0), n / parts);
  for (std::size_t q = p; q < parts; ++q) body(n * q / parts, n * (q + 1) / parts);
  for (std::thread& t : threads) t.join();
}

}  // namespace hedge::detail
