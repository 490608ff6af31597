// Bulk memory (util/bulk_memory.h): large arrays from mmap, optionally on huge pages. The
// contents must be exactly what ordinary vectors hold, on both sides of the size threshold.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>

#include "framework/util/bulk_memory.h"

using namespace subdiv;

TEST_CASE("bulk vectors and resize_bulk hold what ordinary vectors hold") {
  for (const std::size_t n : {std::size_t(10), kBulkBytes / sizeof(double) + 12345}) {
    BulkVector<double> bulk;
    std::vector<double> plain;
    for (std::size_t i = 0; i < n; ++i) bulk.push_back(double(i) * 0.5), plain.push_back(double(i) * 0.5);
    CHECK(std::equal(bulk.begin(), bulk.end(), plain.begin(), plain.end()));
    BulkVector<double> moved = std::move(bulk);
    CHECK(moved.size() == n);
    CHECK(moved.back() == plain.back());
    std::vector<int> a, b;
    resize_bulk(a, n);
    b.resize(n);
    CHECK(a == b);  // value-initialised: zeros
    assign_bulk(a, n, 7);
    CHECK(std::accumulate(a.begin(), a.end(), std::int64_t(0)) == std::int64_t(7) * std::int64_t(n));
    reserve_bulk(b, 2 * n);
    CHECK(b.capacity() >= 2 * n);
    CHECK(b.size() == n);
  }
}

TEST_CASE("lazy bulk memory is zero and 2 MB aligned, transient vectors hold what ordinary vectors hold") {
  constexpr std::size_t kHuge = std::size_t(2) << 20;
  for (const std::size_t bytes : {std::size_t(100), kHuge + 4096 + 7, 5 * kHuge}) {
    auto* data = static_cast<unsigned char*>(allocate_lazy_bulk(bytes));
    CHECK(reinterpret_cast<std::uintptr_t>(data) % kHuge == 0);
    // Zero as it comes (anonymous memory), read before any write and after writes elsewhere.
    CHECK(std::all_of(data, data + bytes, [](unsigned char x) { return x == 0; }));
    data[0] = 1, data[bytes - 1] = 2;
    CHECK(std::count(data, data + bytes, 0) == std::ptrdiff_t(bytes) - 2);
    release_lazy_bulk(data, bytes);
  }
  // Both sides of the 2 MB threshold: the same contents as an ordinary vector, growing and moved.
  for (const std::size_t n : {std::size_t(10), kHuge / sizeof(int) + 12345}) {
    TransientVector<int> t;
    std::vector<int> plain;
    grow(t, n);
    for (std::size_t i = 0; i < n; ++i) t[i] = int(i) * 3, plain.push_back(int(i) * 3);
    for (int i = 0; i < 1000; ++i) t.push_back(-i), plain.push_back(-i);
    TransientVector<int> moved = std::move(t);
    CHECK(std::equal(moved.begin(), moved.end(), plain.begin(), plain.end()));
  }
}

TEST_CASE("a transient vector's new elements are poisoned like a scratch vector's") {
  const bool was = scratch_poison();
  scratch_poison() = true;
  TransientVector<std::int32_t> t;
  grow(t, (std::size_t(2) << 20) / sizeof(std::int32_t) + 3);  // past the threshold: lazy bulk memory
  scratch_poison() = was;
  CHECK(t.front() == std::int32_t(0xA5A5A5A5));
  CHECK(t.back() == std::int32_t(0xA5A5A5A5));
}
