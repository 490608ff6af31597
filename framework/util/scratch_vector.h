#pragma once
// Vectors for arrays that are written in full before they are read.
//
// std::vector<int>::resize zero-fills in the calling thread. For a level's arrays (the last
// level's face corners of a million-face mesh are 256 MB) that fill is serial work, and a
// page first touched by the filling thread, which a parallel pass then overwrites at once.
// vector value-initialises new elements through its allocator's construct(p)
// (allocator_traits, [container.requirements]); an allocator whose construct(p)
// default-initialises leaves them as they come, so the first write is the parallel one,
// which also places the pages (first touch). resize(n, value) and assign(n, value) still
// fill: use them for arrays that are not written in full.
//
// Checking that every element is written before it is read: with the environment variable
// SUBDIV_POISON_SCRATCH=1 (or scratch_poison() set by a test), grow() and the sizing helpers
// of util/bulk_memory.h and util/resize_side_by_side.h fill new elements with the byte 0xA5
// (an index of -1515870811, a double of about -4e-130), so a read of an unwritten element
// gives other bits or an out-of-range index. The unit tests refine both ways and compare
// (tests/unit/engine/scratch_poison_test.cpp); the whole suite can run with it set. The fill
// is not in construct(p): a branch per element would keep the loop that resize now skips.
#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace subdiv {

// Whether new scratch elements are poisoned (SUBDIV_POISON_SCRATCH=1 at start-up, or set
// by a test while no refinement runs).
bool& scratch_poison();
void poison_bytes(void* data, std::size_t bytes);

template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  using value_type = T;
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept(noexcept(::new (static_cast<void*>(p)) U)) {
    ::new (static_cast<void*>(p)) U;  // default-, not value-initialised
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// resize() leaves new elements uninitialised (for trivial T); everything else as std::vector.
template <class T>
using ScratchVector = std::vector<T, DefaultInitAllocator<T>>;

// Contents compared with a std::vector (found by argument-dependent lookup; C++20 gives the
// reversed order too), so that tests and callers compare arrays as before.
template <class T>
bool operator==(const ScratchVector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
}

// v.resize(n), new elements poisoned when scratch_poison() is set (else left as they come).
template <class T, class A>
void grow(std::vector<T, A>& v, std::size_t n) {
  const std::size_t old = v.size();
  v.resize(n);
  if constexpr (std::is_same_v<A, DefaultInitAllocator<T>>)
    if (n > old && scratch_poison()) poison_bytes(v.data() + old, (n - old) * sizeof(T));
}

}  // namespace subdiv
