#include "framework/util/bulk_memory.h"

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <string_view>
#include <sys/mman.h>

namespace subdiv {

namespace {

// Off unless SUBDIV_HUGE_PAGES=1: with the kernel's THP defrag mode `madvise`, advised
// ranges wait for direct compaction when memory is fragmented, and on the benchmark
// machine that cost more than the page faults it saved as often as not
// (docs/benchmarks.md).
bool huge_pages_wanted() {
  static const bool wanted = [] {
    const char* setting = std::getenv("SUBDIV_HUGE_PAGES");
    return setting && std::string_view(setting) == "1";
  }();
  return wanted;
}

std::atomic<bool> reuse_heap{false};

constexpr std::size_t kPage = 4096;
std::size_t whole_pages(std::size_t bytes) { return (bytes + kPage - 1) / kPage * kPage; }

}  // namespace

void reuse_bulk_memory(bool reuse) { reuse_heap.store(reuse); }

void advise_huge_pages(void* data, std::size_t bytes) {
  if (!huge_pages_wanted()) return;
#ifdef MADV_HUGEPAGE
  constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
  if (end > begin) (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // advice only
#else
  (void)data, (void)bytes;
#endif
}

void* allocate_bulk(std::size_t bytes) {
  if (reuse_heap.load(std::memory_order_relaxed)) {
    void* data = std::aligned_alloc(kPage, whole_pages(bytes));
    if (!data) throw std::bad_alloc();
    return data;
  }
  void* data = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (data == MAP_FAILED) throw std::bad_alloc();
  advise_huge_pages(data, bytes);
  return data;
}

// The mapping is made 2 MB longer and cut to a 2 MB boundary, so that every whole 2 MB of
// the array can be one huge page.
void* allocate_lazy_bulk(std::size_t bytes) {
  constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
  const std::size_t length = whole_pages(bytes);
  void* raw = mmap(nullptr, length + kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto begin = reinterpret_cast<std::uintptr_t>(raw);
  const auto aligned = (begin + kHuge - 1) & ~(kHuge - 1);
  if (aligned > begin) munmap(raw, aligned - begin);
  const std::uintptr_t end = begin + length + kHuge;
  if (end > aligned + length) munmap(reinterpret_cast<void*>(aligned + length), end - aligned - length);
  void* data = reinterpret_cast<void*>(aligned);
#ifdef MADV_HUGEPAGE
  if (length >= kHuge) (void)madvise(data, length, MADV_HUGEPAGE);  // advice only
#endif
  return data;
}

void release_lazy_bulk(void* data, std::size_t bytes) { munmap(data, whole_pages(bytes)); }

void release_bulk(void* data, std::size_t bytes) {
  if (reuse_heap.load(std::memory_order_relaxed)) return std::free(data);
  munmap(data, bytes);
}

}  // namespace subdiv
