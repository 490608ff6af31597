#pragma once
// Vectors for scratch arrays that are written in full before they are read.
//
// std::vector<int>::resize zero-fills in the calling thread. For the corner arrays of a
// million-face mesh (16 MB each) that fill is serial work that a parallel pass overwrites
// at once. vector value-initialises new elements through its allocator's construct(p)
// (allocator_traits, [container.requirements]); an allocator whose construct(p)
// default-initialises leaves them as they come, so the first write is the parallel one.
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace subdiv {

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

}  // namespace subdiv
