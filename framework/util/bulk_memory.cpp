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

void* allocate_zeroed_bulk(std::size_t bytes) {
#ifdef MAP_POPULATE
  constexpr int kPopulate = MAP_POPULATE;
#else
  constexpr int kPopulate = 0;
#endif
  void* data = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | kPopulate, -1, 0);
  if (data == MAP_FAILED) throw std::bad_alloc();
  return data;
}

void release_zeroed_bulk(void* data, std::size_t bytes) { munmap(data, bytes); }

void release_bulk(void* data, std::size_t bytes) {
  if (reuse_heap.load(std::memory_order_relaxed)) return std::free(data);
  munmap(data, bytes);
}

}  // namespace subdiv
