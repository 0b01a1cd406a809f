// A global operator new that counts, for the tests that the packet path allocates nothing.
// It replaces the program's operator new: include it in exactly one file of a test program.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace smcbip::pus::testing {
/// The number of calls of the global operator new so far.
inline std::atomic<std::size_t> allocations{0};
}  // namespace smcbip::pus::testing

// Out of line: inlined into a caller (the tests build at -O1 in CI), gcc would pair the free() in
// operator delete with the caller's operator new and warn of a mismatch (-Wmismatched-new-delete).
__attribute__((noinline)) void* operator new(std::size_t size) {
  smcbip::pus::testing::allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
__attribute__((noinline)) void operator delete(void* p) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete(void* p, std::size_t) noexcept { std::free(p); }
