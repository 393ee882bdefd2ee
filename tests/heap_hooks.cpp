#include "heap_hooks.h"

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

std::atomic<bool> g_fail_armed{false};
std::atomic<long> g_fail_countdown{0};
std::atomic<long> g_allocations{0};
std::atomic<std::size_t> g_held{0};
std::atomic<std::size_t> g_peak{0};

void* allocate(std::size_t n, std::size_t align) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (g_fail_armed.load(std::memory_order_relaxed) && g_fail_countdown.fetch_sub(1) == 0) {
    g_fail_armed = false;
    throw std::bad_alloc();
  }
  void* p = nullptr;
  if (align <= alignof(std::max_align_t)) {
    p = std::malloc(n ? n : 1);
  } else if (posix_memalign(&p, align, n ? n : 1) != 0) {
    p = nullptr;
  }
  if (!p) throw std::bad_alloc();
  const std::size_t size = malloc_usable_size(p);
  const std::size_t held = g_held.fetch_add(size, std::memory_order_relaxed) + size;
  std::size_t peak = g_peak.load(std::memory_order_relaxed);
  while (held > peak && !g_peak.compare_exchange_weak(peak, held, std::memory_order_relaxed)) {
  }
  return p;
}

void* allocate_or_null(std::size_t n) noexcept {
  try {
    return allocate(n, 0);
  } catch (...) {
    return nullptr;
  }
}

void release(void* p) noexcept {
  if (p == nullptr) return;
  g_held.fetch_sub(malloc_usable_size(p), std::memory_order_relaxed);
  std::free(p);
}

}  // namespace

namespace hedge::test {

std::size_t heap_held() { return g_held.load(); }

long heap_allocations() { return g_allocations.load(); }

std::size_t heap_peak_during(void (*f)(void*), void* context) {
  const std::size_t start = g_held.load();
  g_peak.store(start);
  f(context);
  return g_peak.load() - start;
}

void fail_allocation_after(long countdown) {
  g_fail_countdown = countdown;
  g_fail_armed = true;
}

void disarm_allocation_failure() { g_fail_armed = false; }

}  // namespace hedge::test

void* operator new(std::size_t n) { return allocate(n, 0); }
void* operator new[](std::size_t n) { return allocate(n, 0); }
void* operator new(std::size_t n, std::align_val_t a) { return allocate(n, std::size_t(a)); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocate(n, std::size_t(a)); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return allocate_or_null(n); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return allocate_or_null(n); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
