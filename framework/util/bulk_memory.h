#pragma once
// Large flat arrays on transparent huge pages.
//
// Refining a million-face mesh writes gigabytes of fresh memory: topology, stencil tables,
// positions. With 4 KB pages every 4 KB of it costs a page fault, and on virtual machines
// the faults, not the arithmetic, can dominate (docs/benchmarks.md). Linux's THP mode is
// often `madvise`, which gives 2 MB pages only to ranges that ask for them. These helpers
// reserve an array's memory and, when SUBDIV_HUGE_PAGES=1 is set, ask for huge pages before
// it is first touched (off by default: see bulk_memory.cpp). Bulk memory for short-lived
// arrays comes straight from mmap and goes back at once when freed, which keeps the peak
// down. The contents are the same either way.
#include <algorithm>
#include <cstddef>
#include <memory>
#include <type_traits>
#include <vector>

#include "framework/util/scratch_vector.h"

namespace subdiv {

// Below this many bytes an array is left to the allocator's usual pages.
constexpr std::size_t kBulkBytes = std::size_t(1) << 20;

// Asks for huge pages on the 2 MB-aligned part of [data, data + bytes); a no-op where
// madvise or THP is not available.
void advise_huge_pages(void* data, std::size_t bytes);

// Memory of `bytes` straight from the system (mmap) with huge pages advised, and back to
// it on release: unlike heap blocks, freed bulk memory leaves the process at once, so
// arrays that replace each other do not add up in the peak. Throws std::bad_alloc.
void* allocate_bulk(std::size_t bytes);
void release_bulk(void* data, std::size_t bytes);

// Zeroed memory of `bytes`, page-aligned, on transparent huge pages where the kernel gives
// them (MADV_HUGEPAGE whatever SUBDIV_HUGE_PAGES says), each page placed at its first touch;
// for an array written here and there over a long time, part of it perhaps never (a limit
// surface's per-face slots), or written in full and soon dropped (TransientVector). On a virtual machine the first touch of a fresh 4 KB page
// costs the guest's page fault and the host's: 10 MB of such pages took 30-60 ms to map and
// first read (MAP_POPULATE, then a read per 64 bytes), 0.4-9 ms on 2 MB pages (docs/limit.md,
// "Fresh pages, fewer"). Back with release_lazy_bulk. Throws std::bad_alloc.
void* allocate_lazy_bulk(std::size_t bytes);
void release_lazy_bulk(void* data, std::size_t bytes);

// For programs that refine again and again (animation, interactive editing, benchmarks):
// with `reuse` on, bulk memory comes from the heap and goes back to it, so the next
// refinement finds pages already touched instead of faulting in fresh ones (pair it with
// mallopt(M_TRIM_THRESHOLD) and mallopt(M_MMAP_MAX) so the heap keeps them). Off by default:
// the peak is lower when freed arrays leave the process. Set it while no bulk memory is live.
void reuse_bulk_memory(bool reuse);

// An allocator for vectors that grow large and die young (per-chunk buffers): bulk memory
// from kBulkBytes up, the ordinary heap below.
template <class T>
struct BulkAllocator {
  using value_type = T;
  BulkAllocator() = default;
  template <class U>
  BulkAllocator(const BulkAllocator<U>&) {}
  T* allocate(std::size_t n) {
    if (n * sizeof(T) < kBulkBytes) return std::allocator<T>().allocate(n);
    return static_cast<T*>(allocate_bulk(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) {
    if (n * sizeof(T) < kBulkBytes) return std::allocator<T>().deallocate(p, n);
    release_bulk(p, n * sizeof(T));
  }
  template <class U>
  bool operator==(const BulkAllocator<U>&) const { return true; }
};

template <class T>
using BulkVector = std::vector<T, BulkAllocator<T>>;

// An allocator for scratch arrays written in full and dropped within one call (a level
// builder's corner tables): from 2 MB up, lazy bulk memory (allocate_lazy_bulk: huge pages,
// each placed at its first write), the ordinary heap below; new elements left as they come,
// as a ScratchVector's (util/scratch_vector.h).
template <class T>
struct TransientAllocator : DefaultInitAllocator<T> {
  using value_type = T;
  template <class U>
  struct rebind {
    using other = TransientAllocator<U>;
  };
  static constexpr std::size_t kLazyBytes = std::size_t(2) << 20;
  TransientAllocator() = default;
  template <class U>
  TransientAllocator(const TransientAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
    if (n * sizeof(T) < kLazyBytes) return std::allocator<T>().allocate(n);
    return static_cast<T*>(allocate_lazy_bulk(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) {
    if (n * sizeof(T) < kLazyBytes) return std::allocator<T>().deallocate(p, n);
    release_lazy_bulk(p, n * sizeof(T));
  }
  template <class U>
  bool operator==(const TransientAllocator<U>&) const { return true; }
};

template <class T>
using TransientVector = std::vector<T, TransientAllocator<T>>;

// grow() for a TransientVector: new elements poisoned as a ScratchVector's are.
template <class T>
void grow(TransientVector<T>& v, std::size_t n) {
  const std::size_t old = v.size();
  v.resize(n);
  if (n > old && scratch_poison()) poison_bytes(v.data() + old, (n - old) * sizeof(T));
}

// v.resize(n), with huge pages advised before the new memory is first touched. A
// ScratchVector's new elements are left as they come (util/scratch_vector.h: grow).
template <class T, class A>
void resize_bulk(std::vector<T, A>& v, std::size_t n) {
  if (n * sizeof(T) >= kBulkBytes && v.capacity() < n) {
    v.reserve(n);
    advise_huge_pages(v.data(), v.capacity() * sizeof(T));
  }
  grow(v, n);
}

// v.assign(n, value), likewise.
template <class T, class A>
void assign_bulk(std::vector<T, A>& v, std::size_t n, const std::type_identity_t<T>& value) {
  v.clear();
  resize_bulk(v, n);
  std::fill(v.begin(), v.end(), value);
}

// v.reserve(n), likewise (for arrays filled by push_back).
template <class T, class A>
void reserve_bulk(std::vector<T, A>& v, std::size_t n) {
  if (v.capacity() >= n) return;
  v.reserve(n);
  if (n * sizeof(T) >= kBulkBytes) advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace subdiv
