#include "framework/analysis/curve/curve_basis.h"

#include <cmath>
#include <numeric>
#include <fmt/format.h>

#include "framework/analysis/curve/curve_eigen.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

constexpr int kMaxCentreSteps = 6;

long floor_div(long a, long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
long ceil_div(long a, long b) { return -floor_div(-a, b); }

// phi(num / den) through the refinement equation until the argument is an integer.
double phi_at(const CurveMask& mask, const BasisSamples& s, long num, long den) {
  if (num % den == 0) {
    const long k = num / den - s.integers_first;
    return k >= 0 && k < long(s.at_integers.size()) ? s.at_integers[size_t(k)] : 0.0;
  }
  double sum = 0.0;
  for (int i = mask.first; i <= mask.last(); ++i)
    if (mask.at(i) != 0.0) sum += mask.at(i) * phi_at(mask, s, long(mask.arity) * num - long(i) * den, den);
  return sum;
}

}  // namespace

BasisSamples sample_basis(const CurveMask& raw, const std::string& scheme) {
  const CurveMask mask = trimmed(raw);
  const long m = mask.arity, first = mask.first, last = mask.last();
  BasisSamples s;
  // phi at the integers is the limit mask at t = 0 (Halstead, Kass & DeRose 1993): the left eigenvector
  // of 1 of the local subdivision matrix, whose neighbourhood j holds weight phi(-j).
  const LocalSubdivisionMatrix local = local_subdivision_matrix(mask);
  if (local.size() == 0) throw Error(fmt::format("curve scheme {}: its mask has no integer in its support", subdiv::quoted(scheme)));
  const LocalEigenAnalysis eigen = analyse_local_matrix(local);
  if (!eigen.has_limit_mask)
    throw Error(fmt::format("curve scheme {}: its limit function has no values at the integers (1 is not the "
                            "simple dominant eigenvalue of its local subdivision matrix), so the scheme has no limit "
                            "points; check it with `subdiv analyze {}`",
                            subdiv::quoted(scheme), scheme));
  const int count = local.size();
  s.integers_first = -(local.first_index + count - 1);
  s.at_integers.assign(eigen.limit_mask.rbegin(), eigen.limit_mask.rend());
  // The mask's round-off is snapped to zero; divide by what is left, so that an
  // interpolatory scheme's phi(0) is exactly 1.
  const double sum = std::accumulate(s.at_integers.begin(), s.at_integers.end(), 0.0);
  for (double& v : s.at_integers) v /= sum;

  // The centre c = (first + last) / (2 (m - 1)) = num / den.
  const long den = 2 * (m - 1), num = first + last;
  long reach = num;
  int steps = 0;
  while (reach % den != 0 && steps < kMaxCentreSteps) reach *= m, ++steps;
  if (reach % den != 0)
    throw Error(fmt::format("curve scheme {}: the centre {}/{} of its limit function is not reached by "
                            "refinement, so its control points have no limit point to interpolate",
                            subdiv::quoted(scheme), num, den));
  s.centre = double(num) / double(den);
  // Offsets d with c + d inside the support.
  s.centre_first = int(ceil_div(2 * first - num, den));
  const int centre_last = int(floor_div(2 * last - num, den));
  for (int d = s.centre_first; d <= centre_last; ++d) s.at_centre.push_back(phi_at(mask, s, num + long(d) * den, den));
  return s;
}

}  // namespace subdiv
