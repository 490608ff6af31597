#include "framework/analysis/curve/curve_local_matrix.h"

#include "framework/analysis/curve/curve_integer.h"

namespace subdiv {

LocalSubdivisionMatrix local_subdivision_matrix(const CurveMask& mask) {
  const CurveMask a = trimmed(mask);  // validates
  const int m = a.arity;
  // Integers j with -last/(m-1) <= j <= -first/(m-1) (see the header).
  const int lo = ceil_div(-a.last(), m - 1);
  const int hi = floor_div(-a.first, m - 1);
  LocalSubdivisionMatrix out;
  out.first_index = lo;
  if (lo > hi) return out;
  const std::size_t n = static_cast<std::size_t>(hi - lo + 1);
  out.rows.assign(n, std::vector<double>(n, 0.0));
  // New point p from old point j with weight a_{p - m j} (curve_mask.h).
  for (int p = lo; p <= hi; ++p)
    for (int j = lo; j <= hi; ++j)
      out.rows[static_cast<std::size_t>(p - lo)][static_cast<std::size_t>(j - lo)] = a.at(p - m * j);
  return out;
}

}  // namespace subdiv
