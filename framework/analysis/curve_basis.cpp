#include "framework/analysis/curve_basis.h"

#include <Eigen/Dense>
#include <cmath>
#include <fmt/format.h>

#include "framework/util/error.h"

namespace subdiv {
namespace {

constexpr double kResidualTolerance = 1e-9;
constexpr int kMaxCentreSteps = 6;
constexpr double kRoundOff = 1e-13;

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
  // Integers inside the support [first, last] / (m - 1).
  s.integers_first = int(ceil_div(first, m - 1));
  const int count = int(floor_div(last, m - 1)) - s.integers_first + 1;
  if (count <= 0) throw Error(fmt::format("curve scheme '{}': its mask has no integer in its support", scheme));
  // (A - I) phi = 0 and sum phi = 1, solved together in the least-squares sense.
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(count + 1, count);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(count + 1);
  for (int k = 0; k < count; ++k) {
    for (int l = 0; l < count; ++l)
      system(k, l) = mask.at(int(m * (k + s.integers_first) - (l + s.integers_first)));
    system(k, k) -= 1.0;
  }
  system.row(count).setOnes();
  rhs(count) = 1.0;
  const Eigen::VectorXd phi = system.colPivHouseholderQr().solve(rhs);
  if (!phi.allFinite() || (system * phi - rhs).norm() > kResidualTolerance)
    throw Error(fmt::format("curve scheme '{}': its limit function has no values at the integers (the system "
                            "phi(k) = sum a_(m k - l) phi(l) has no solution summing to one), so the scheme has no "
                            "limit points; check it with `subdiv analyze {}`",
                            scheme, scheme));
  // Values that are zero in exact arithmetic (interpolatory schemes: phi(k) = 0 for k != 0)
  // come back as round-off; clean them so the rows have no 1e-19 terms.
  double sum = 0.0;
  for (int k = 0; k < count; ++k) {
    const double v = std::abs(phi(k)) < kRoundOff ? 0.0 : phi(k);
    s.at_integers.push_back(v);
    sum += v;
  }
  for (double& v : s.at_integers) v /= sum;

  // The centre c = (first + last) / (2 (m - 1)) = num / den.
  const long den = 2 * (m - 1), num = first + last;
  long reach = num;
  int steps = 0;
  while (reach % den != 0 && steps < kMaxCentreSteps) reach *= m, ++steps;
  if (reach % den != 0)
    throw Error(fmt::format("curve scheme '{}': the centre {}/{} of its limit function is not reached by "
                            "refinement, so its control points have no limit point to interpolate",
                            scheme, num, den));
  s.centre = double(num) / double(den);
  // Offsets d with c + d inside the support.
  s.centre_first = int(ceil_div(2 * first - num, den));
  const int centre_last = int(floor_div(2 * last - num, den));
  for (int d = s.centre_first; d <= centre_last; ++d) s.at_centre.push_back(phi_at(mask, s, num + long(d) * den, den));
  return s;
}

}  // namespace subdiv
