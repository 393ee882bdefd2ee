// The unit-test binary's global operator new and delete (tests/heap_hooks.cpp): they count the
// bytes held, for tests that bound what a call allocates, and can throw std::bad_alloc at a chosen
// allocation, for tests of the strong guarantee. Unarmed, they are malloc and free.
#pragma once

#include <cstddef>

namespace hedge::test {

//! Bytes held through operator new now (malloc's usable size of each block).
std::size_t heap_held();

//! Calls of operator new so far.
long heap_allocations();

//! The most bytes held at once while f() ran, above what was held when it started.
std::size_t heap_peak_during(void (*f)(void*), void* context);
template <typename F>
std::size_t heap_peak_during(F&& f) {
  return heap_peak_during([](void* c) { (*static_cast<F*>(c))(); }, &f);
}

//! The allocation after `countdown` more allocations throws std::bad_alloc, once; then the hook
//! disarms itself.
void fail_allocation_after(long countdown);
//! Disarms fail_allocation_after().
void disarm_allocation_failure();

}  // namespace hedge::test
