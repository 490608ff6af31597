#include "meshlibs_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace subdiv_bench {
namespace {

// 21 bits per axis, offset so that small negative cells pack too.
std::uint64_t cell_key(std::int64_t i, std::int64_t j, std::int64_t k) {
  constexpr std::int64_t kOffset = 1 << 20, kMask = (1 << 21) - 1;
  return (std::uint64_t((i + kOffset) & kMask) << 42) | (std::uint64_t((j + kOffset) & kMask) << 21) |
         std::uint64_t((k + kOffset) & kMask);
}

std::int64_t cell_of(double x, double size) { return std::int64_t(std::floor(x / size)); }

bool region_sampled(std::int64_t i, std::int64_t j, std::int64_t k, std::uint64_t modulus) {
  return key_mix(cell_key(i, j, k)) % modulus == 0;
}

// Nearest-partner search over one side's records: a grid of cells much larger than the
// tolerance and much smaller than the spacing of the points, sorted by cell.
class PointGrid {
public:
  static constexpr double kCell = 1e-4;

  explicit PointGrid(const std::vector<CheckRecord>& records) : records_(records) {
    cells_.reserve(records.size());
    for (std::uint32_t r = 0; r < records.size(); ++r) {
      const double* p = records[r].xyz;
      cells_.push_back({cell_key(cell_of(p[0], kCell), cell_of(p[1], kCell), cell_of(p[2], kCell)), r});
    }
    std::sort(cells_.begin(), cells_.end());
  }

  // The record nearest to p (in the largest coordinate difference) among the 27 cells
  // around it, and that difference; -1 when none.
  std::pair<std::int64_t, double> nearest(const double* p) const {
    std::int64_t best = -1;
    double best_diff = std::numeric_limits<double>::infinity();
    const std::int64_t ci = cell_of(p[0], kCell), cj = cell_of(p[1], kCell), ck = cell_of(p[2], kCell);
    for (std::int64_t di = -1; di <= 1; ++di)
      for (std::int64_t dj = -1; dj <= 1; ++dj)
        for (std::int64_t dk = -1; dk <= 1; ++dk) {
          const std::uint64_t key = cell_key(ci + di, cj + dj, ck + dk);
          auto it = std::lower_bound(cells_.begin(), cells_.end(), std::pair<std::uint64_t, std::uint32_t>{key, 0});
          for (; it != cells_.end() && it->first == key; ++it) {
            const double* q = records_[it->second].xyz;
            const double diff = std::max({std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2])});
            if (diff < best_diff) best_diff = diff, best = it->second;
          }
        }
    return {best, best_diff};
  }

private:
  const std::vector<CheckRecord>& records_;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> cells_;
};

// Every strict point of `from` against `to`, all of them (so that maxdiff says how far
// apart the two sides are, not only that they are): adds to `m`, false if any failed.
bool match_one_way(const std::vector<CheckRecord>& from, const std::vector<CheckRecord>& to, double tolerance,
                   PointSetMatch& m) {
  const PointGrid grid(to);
  std::vector<bool> claimed(to.size(), false);
  bool ok = true;
  for (const CheckRecord& r : from) {
    if (r.key != 1) continue;
    const auto [partner, diff] = grid.nearest(r.xyz);
    m.maxdiff = std::max(m.maxdiff, partner < 0 || std::isnan(diff) ? INFINITY : diff);
    ++m.compared;
    if (partner < 0 || !(diff <= tolerance)) {
      ok = false;
    } else if (claimed[size_t(partner)]) {
      m.problem = "two points share one partner";
      ok = false;
    } else {
      claimed[size_t(partner)] = true;
    }
  }
  return ok;
}

}  // namespace

std::vector<CheckRecord> sample_points(const std::vector<double>& xyz, std::uint64_t modulus) {
  std::vector<CheckRecord> records;
  if (modulus == 0) return records;
  for (size_t v = 0; 3 * v < xyz.size(); ++v) {
    const double* p = &xyz[3 * v];
    std::array<std::int64_t, 3> lo, hi;
    for (int k = 0; k < 3; ++k) lo[k] = cell_of(p[k] - kSlack, kRegionSize), hi[k] = cell_of(p[k] + kSlack, kRegionSize);
    const bool strict = region_sampled(cell_of(p[0], kRegionSize), cell_of(p[1], kRegionSize), cell_of(p[2], kRegionSize), modulus);
    bool near = strict;
    for (std::int64_t i = lo[0]; i <= hi[0] && !near; ++i)
      for (std::int64_t j = lo[1]; j <= hi[1] && !near; ++j)
        for (std::int64_t k = lo[2]; k <= hi[2] && !near; ++k) near = region_sampled(i, j, k, modulus);
    if (near) records.push_back({strict ? 1u : 0u, {p[0], p[1], p[2]}});
  }
  return records;
}

PointSetMatch match_point_sets(const std::vector<CheckRecord>& a, const std::vector<CheckRecord>& b, double tolerance) {
  PointSetMatch m;
  const bool a_in_b = match_one_way(a, b, tolerance, m);
  m.ok = match_one_way(b, a, tolerance, m) && a_in_b;
  return m;
}

}  // namespace subdiv_bench
