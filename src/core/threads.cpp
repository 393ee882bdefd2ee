#include "hedge/core/threads.h"

#include <atomic>

#if defined(__linux__)
#include <sched.h>
#endif

namespace hedge {

namespace {

std::atomic<unsigned> g_max_threads{0};

//! The cores this process may run on (its affinity mask on Linux), at least 1.
unsigned usable_cores() {
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

}  // namespace

void set_max_threads(unsigned n) { g_max_threads.store(n, std::memory_order_relaxed); }

unsigned max_threads() {
  const unsigned n = g_max_threads.load(std::memory_order_relaxed);
  if (n != 0) return n;
  static const unsigned cores = usable_cores();
  return cores;
}

namespace detail {

std::size_t parallel_parts(std::size_t n, std::size_t grain, std::size_t cap) {
  std::size_t parts =
      std::min<std::size_t>(max_threads(), std::max<std::size_t>(1, n / std::max<std::size_t>(1, grain)));
  if (cap != 0) parts = std::min(parts, cap);
  return std::max<std::size_t>(1, parts);
}

}  // namespace detail

}  // namespace hedge
