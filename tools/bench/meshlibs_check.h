#pragma once
// Do two libraries compute the same points? Their vertex orders differ (each numbers new
// vertices as its own refinement loop creates them), so points are matched by position:
// every sampled point of one side must have a point of the other within the tolerance,
// and no two points may claim the same partner, in both directions. With equal vertex
// counts and points much further apart than the tolerance, that is the same point set.
//
// Sampling picks whole regions of space, so both sides sample the same points without
// knowing each other's order: space is cut into cubes of kRegionSize, and a cube is
// sampled when a hash of its integer coordinates is a multiple of the modulus. A point is
// sent "strict" when its own cube is sampled and "near" when only a cube within kSlack of
// it is, so that a partner that round-off put across a cube face is still sent.
#include <cstdint>
#include <string>
#include <vector>

#include "bench_common.h"

namespace subdiv_bench {

inline constexpr double kRegionSize = 0.02;  // the generated meshes span about 3 units
inline constexpr double kSlack = 1e-6;       // much more than round-off, much less than an edge

// CheckRecord::key is 1 for strict points, 0 for near ones.
std::vector<CheckRecord> sample_points(const std::vector<double>& xyz, std::uint64_t modulus);

struct PointSetMatch {
  bool ok = false;
  std::int64_t compared = 0;  // strict points looked up, both directions together
  double maxdiff = 0;         // largest coordinate difference to the nearest partner (inf: none near)
  std::string problem;        // why not ok, when it is not a distance
};

PointSetMatch match_point_sets(const std::vector<CheckRecord>& a, const std::vector<CheckRecord>& b, double tolerance);

}  // namespace subdiv_bench
