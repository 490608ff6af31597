#include "framework/engine/face_partition.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <fmt/format.h>
#include <limits>
#include <numeric>

#include "framework/util/error.h"

#ifdef SUBDIV_HAVE_METIS
#include <metis.h>
#endif

namespace subdiv {
namespace {

void check_piece_count(const Level& level, int pieces) {
  if (pieces < 1 || pieces > level.face_count())
    throw Error(fmt::format("cannot cut a mesh of {} faces into {} pieces; ask for 1 to {} pieces",
                            level.face_count(), pieces, level.face_count()));
}

std::array<double, 3> centroid(const Level& level, std::span<const double> positions, Index f) {
  std::array<double, 3> c{0, 0, 0};
  for (Index v : level.face(f))
    for (int k = 0; k < 3; ++k) c[k] += positions[3 * size_t(v) + k];
  for (double& x : c) x /= level.face_size(f);
  return c;
}

// Spreads the low 21 bits of x three apart (bit i goes to bit 3i).
std::uint64_t spread_bits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

// Each face's centroid on a 2^21 grid over the mesh's bounding box, bits interleaved.
std::vector<std::uint64_t> morton_codes(const Level& level, std::span<const double> positions) {
  std::vector<std::array<double, 3>> c(level.face_count());
  std::array<double, 3> lo{}, hi{};
  lo.fill(std::numeric_limits<double>::max());
  hi.fill(std::numeric_limits<double>::lowest());
  for (Index f = 0; f < level.face_count(); ++f) {
    c[f] = centroid(level, positions, f);
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[f][k]), hi[k] = std::max(hi[k], c[f][k]);
  }
  std::vector<std::uint64_t> codes(level.face_count());
  for (Index f = 0; f < level.face_count(); ++f) {
    std::uint64_t code = 0;
    for (int k = 0; k < 3; ++k) {
      const double extent = hi[k] - lo[k];
      const double t = extent > 0 ? (c[f][k] - lo[k]) / extent : 0.0;
      code |= spread_bits(std::uint64_t(t * double((1 << 21) - 1))) << k;
    }
    codes[f] = code;
  }
  return codes;
}

#ifdef SUBDIV_HAVE_METIS
// The faces' dual graph in METIS's CSR form: faces joined across each edge they share.
void dual_graph(const Level& level, std::vector<idx_t>& xadj, std::vector<idx_t>& adjncy) {
  xadj.assign(1, 0);
  for (Index f = 0; f < level.face_count(); ++f) {
    const size_t first = adjncy.size();
    for (Index e : level.face_edge_list(f))
      for (Index g : level.faces_of_edge(e))
        if (g != f && std::find(adjncy.begin() + ptrdiff_t(first), adjncy.end(), g) == adjncy.end())
          adjncy.push_back(g);
    xadj.push_back(idx_t(adjncy.size()));
  }
}

// METIS's k-way partition, or empty when it fails or leaves a piece without faces.
std::vector<int> metis_partition(const Level& level, int pieces) {
  std::vector<idx_t> xadj, adjncy;
  dual_graph(level, xadj, adjncy);
  idx_t vertices = level.face_count(), constraints = 1, parts = pieces, cut = 0;
  std::vector<idx_t> part(level.face_count());
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;  // the same pieces on every rank and every run
  const int status = METIS_PartGraphKway(&vertices, &constraints, xadj.data(), adjncy.data(), nullptr, nullptr,
                                         nullptr, &parts, nullptr, nullptr, options, &cut, part.data());
  if (status != METIS_OK) return {};
  std::vector<int> count(pieces, 0);
  for (idx_t p : part) ++count[p];
  if (std::count(count.begin(), count.end(), 0) > 0) return {};
  return std::vector<int>(part.begin(), part.end());
}
#endif

}  // namespace

bool partition_uses_metis() {
#ifdef SUBDIV_HAVE_METIS
  return true;
#else
  return false;
#endif
}

std::vector<int> partition_faces_along_curve(const Level& level, std::span<const double> positions, int pieces) {
  check_piece_count(level, pieces);
  const std::vector<std::uint64_t> codes = morton_codes(level, positions);
  std::vector<Index> order(level.face_count());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return codes[a] < codes[b]; });
  std::vector<int> piece(level.face_count());
  const size_t n = order.size();
  for (size_t i = 0; i < n; ++i) piece[order[i]] = int(i * size_t(pieces) / n);
  return piece;
}

FacePartition partition_faces(const Level& level, std::span<const double> positions, int pieces) {
  check_piece_count(level, pieces);
  if (pieces == 1) return {std::vector<int>(level.face_count(), 0), "one piece"};
#ifdef SUBDIV_HAVE_METIS
  if (std::vector<int> metis = metis_partition(level, pieces); !metis.empty()) return {std::move(metis), "METIS k-way"};
#endif
  return {partition_faces_along_curve(level, positions, pieces), "Morton curve"};
}

}  // namespace subdiv
