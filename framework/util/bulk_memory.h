#pragma once
// Large flat arrays on transparent huge pages.
//
// Refining a million-face mesh writes gigabytes of fresh memory: topology, stencil tables,
// positions. With 4 KB pages every 4 KB of it costs a page fault, and on virtual machines
// the faults, not the arithmetic, dominate (measured in docs/benchmarks.md: system time
// several times the user time). Linux's default THP mode is often `madvise`, which gives
// 2 MB pages only to ranges that ask for them. These helpers reserve an array's memory,
// ask for huge pages, and only then touch it. Small arrays, and systems without THP, take
// the ordinary path; the contents are the same either way.
#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace subdiv {

// Below this many bytes an array is left to the allocator's usual pages.
constexpr std::size_t kBulkBytes = std::size_t(4) << 20;

// Asks for huge pages on the 2 MB-aligned part of [data, data + bytes); a no-op where
// madvise or THP is not available.
void advise_huge_pages(void* data, std::size_t bytes);

// v.resize(n), with huge pages advised before the new memory is first touched.
template <class T>
void resize_bulk(std::vector<T>& v, std::size_t n) {
  if (n * sizeof(T) >= kBulkBytes && v.capacity() < n) {
    v.reserve(n);
    advise_huge_pages(v.data(), v.capacity() * sizeof(T));
  }
  v.resize(n);
}

// v.assign(n, value), likewise.
template <class T>
void assign_bulk(std::vector<T>& v, std::size_t n, const std::type_identity_t<T>& value) {
  v.clear();
  resize_bulk(v, n);
  std::fill(v.begin(), v.end(), value);
}

// v.reserve(n), likewise (for arrays filled by push_back).
template <class T>
void reserve_bulk(std::vector<T>& v, std::size_t n) {
  if (v.capacity() >= n) return;
  v.reserve(n);
  if (n * sizeof(T) >= kBulkBytes) advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace subdiv
