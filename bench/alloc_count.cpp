// Counting replacements of the global operator new / delete (see alloc_count.h).
#include "alloc_count.h"

#include <malloc.h>

#include <cstdlib>
#include <new>

namespace {

bool g_counting = false;
bench::alloc::Stats g_stats;

inline void on_alloc(void* p) {
  if (g_counting && p) {
    g_stats.live += static_cast<std::int64_t>(malloc_usable_size(p));
    g_stats.allocations += 1;
    if (g_stats.live > g_stats.peak) g_stats.peak = g_stats.live;
  }
}
inline void on_free(void* p) {
  if (g_counting && p) g_stats.live -= static_cast<std::int64_t>(malloc_usable_size(p));
}

void* allocate(std::size_t n) {
  void* p = std::malloc(n ? n : 1);
  if (!p) throw std::bad_alloc();
  on_alloc(p);
  return p;
}
void* allocate_aligned(std::size_t n, std::align_val_t al) {
  std::size_t a = static_cast<std::size_t>(al);
  if (a < sizeof(void*)) a = sizeof(void*);
  void* p = nullptr;
  if (posix_memalign(&p, a, n ? n : 1) != 0) throw std::bad_alloc();
  on_alloc(p);
  return p;
}
void release(void* p) noexcept {
  on_free(p);
  std::free(p);
}

}  // namespace

namespace bench::alloc {
void start() {
  g_stats = {};
  g_counting = true;
}
Stats stop() {
  g_counting = false;
  return g_stats;
}
}  // namespace bench::alloc

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return allocate(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return allocate(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new(std::size_t n, std::align_val_t a) { return allocate_aligned(n, a); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocate_aligned(n, a); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete(void* p, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { release(p); }
