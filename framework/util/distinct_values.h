#pragma once
// The distinct small non-negative integers found over a range of items, ascending, in one
// parallel pass: the valences of a level's vertices, the sizes of its sectors.
#include <cstddef>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <vector>

namespace subdiv {

// `report(i, add)` calls add(value) for each value item i has (none, one or several; value
// >= 0). Memory is one byte per value up to the largest.
template <class Item, class Report>
std::vector<int> distinct_values(Item count, Item grain, Report report) {
  using Seen = std::vector<char>;
  const Seen seen = tbb::parallel_reduce(
      tbb::blocked_range<Item>(0, count, grain), Seen{},
      [&report](const tbb::blocked_range<Item>& r, Seen s) {
        auto add = [&s](int value) {
          if (size_t(value) >= s.size()) s.resize(size_t(value) + 1, 0);
          s[size_t(value)] = 1;
        };
        for (Item i = r.begin(); i < r.end(); ++i) report(i, add);
        return s;
      },
      [](Seen a, const Seen& b) {
        if (b.size() > a.size()) a.resize(b.size(), 0);
        for (size_t v = 0; v < b.size(); ++v) a[v] |= b[v];
        return a;
      });
  std::vector<int> out;
  for (size_t v = 0; v < seen.size(); ++v)
    if (seen[v]) out.push_back(int(v));
  return out;
}

}  // namespace subdiv
