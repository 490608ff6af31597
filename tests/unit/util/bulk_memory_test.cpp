// Bulk memory (util/bulk_memory.h): large arrays from mmap, optionally on huge pages. The
// contents must be exactly what ordinary vectors hold, on both sides of the size threshold.
#include <doctest/doctest.h>

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
