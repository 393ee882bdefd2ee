// The thread policy of the library, in one place.
//
// Most functions run on the calling thread only. A few split a long loop between worker threads:
// subdivide() (include/hedge/algorithms/subdivide.h), one_sided_distance() and
// hausdorff_distance() (include/hedge/algorithms/distance.h), and fracture_solid()
// (include/hedge/algorithms/fracture_solid.h: its cells, its patch and the measuring of its
// pieces). Each says so in its header; their results do not depend on the number of threads. How
// many they may use is one process-wide setting: set_max_threads(1) keeps every call on the
// calling thread (inside a game's frame, say), set_max_threads(0) (the default) lets them use
// every core the process may run on.
//
// The workers live only for the duration of the call that started them: nothing runs in the
// background between calls, and a call returns only when its workers have finished.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <type_traits>
#include <vector>

namespace hedge {

//! Sets how many threads a call of the library may run on, the calling thread included: 1 runs
//! everything on the calling thread (no worker thread is started), 0 restores the default, the
//! number of cores the process may run on. The setting is process-wide and may be changed from any
//! thread at any time; a call already running keeps the count it started with. O(1).
void set_max_threads(unsigned n);

//! The number of threads a call of the library may run on now: what set_max_threads() set, or the
//! number of usable cores (at least 1) when it set 0 or was never called. O(1) once the cores are
//! known.
unsigned max_threads();

namespace detail {

//! How many ranges parallel_ranges(n, body, grain, cap) splits [0, n) into: at most max_threads(),
//! at most cap (0: no cap of its own), and no range shorter than grain. At least 1.
std::size_t parallel_parts(std::size_t n, std::size_t grain, std::size_t cap = 0);

//! Calls body on consecutive ranges covering [0, n), one per part (parallel_parts), each on its own
//! thread but the first, which runs on the calling thread. body is called as body(begin, end) or,
//! if it takes three arguments, body(begin, end, part) with part in [0, parts), so that it can fill
//! per-part scratch. A thread costs some tens of microseconds, hence the grain. If no thread can be
//! started, the remaining ranges run on the calling thread. The body must write only what its range
//! owns and must not throw.
template <typename Body>
void parallel_ranges(std::size_t n, Body&& body, std::size_t grain = std::size_t(1) << 15,
                     std::size_t cap = 0) {
  const std::size_t parts = parallel_parts(n, grain, cap);
  auto run = [&body, n, parts](std::size_t p) {
    if constexpr (std::is_invocable_v<Body&, std::size_t, std::size_t, std::size_t>)
      body(n * p / parts, n * (p + 1) / parts, p);
    else
      body(n * p / parts, n * (p + 1) / parts);
  };
  if (parts <= 1) {
    run(0);
    return;
  }
  std::vector<std::thread> threads;
  threads.reserve(parts - 1);
  std::size_t p = 1;
  try {
    for (; p < parts; ++p) threads.emplace_back(run, p);
  } catch (...) {
    // No thread to be had (a platform without them, or out of resources): the rest runs here.
  }
  run(0);
  for (std::size_t q = p; q < parts; ++q) run(q);
  for (std::thread& t : threads) t.join();
}

//! Calls body(task, worker) for every task in [0, n), on up to parallel_parts(n, 1, cap) threads,
//! the calling thread one of them, with worker in [0, threads) naming the thread (for per-thread
//! scratch). Task 0 runs on the calling thread (worker 0), so what it keeps in thread-local storage
//! is there again at the next call; then each thread takes the lowest task not yet taken, so tasks
//! start in increasing order: put a long task first and the others run beside it. Which thread
//! runs any other task varies from call
//! to call, so the body must write only what its task (or its worker's scratch) owns and must not
//! throw; results then do not depend on the number of threads. A thread costs some tens of
//! microseconds: tasks should be longer than that.
template <typename Body>
void parallel_tasks(std::size_t n, Body&& body, std::size_t cap = 0) {
  const std::size_t threads = parallel_parts(n, 1, cap);
  if (n == 0) return;
  std::atomic<std::size_t> next{1};
  parallel_ranges(
      threads,
      [&body, &next, n](std::size_t, std::size_t, std::size_t worker) {
        if (worker == 0) body(0, 0);
        for (std::size_t task = next.fetch_add(1, std::memory_order_relaxed); task < n;
             task = next.fetch_add(1, std::memory_order_relaxed))
          body(task, worker);
      },
      1, threads);
}

}  // namespace detail

}  // namespace hedge
