#include "framework/limit/box_spline_patch.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "framework/limit/lattice_functions.h"
#include "framework/limit/triangle_patch.h"

namespace subdiv {
namespace {

// A term coef * b0^e0 b1^e1 b2^e2 of basis function f, in the barycentric coordinates
// b0 = 1 - s - t, b1 = s, b2 = t of the triangle (0, 0), (1, 0), (0, 1).
struct Term {
  int f = 0;
  double coef = 0;
  std::array<int, 3> e{};
};

// The basis functions (or one of their derivatives) as terms of one degree, like terms
// combined, in a fixed order (the order the sums take).
struct Polynomials {
  static constexpr size_t kMax = 256;
  std::array<Term, kMax> term{};
  size_t count = 0;
  int degree = 4;

  // Adds a term, combined with a like one (same function, same exponents) when there is one.
  constexpr void add(int f, double coef, const std::array<int, 3>& e) {
    for (size_t i = 0; i < count; ++i)
      if (term[i].f == f && term[i].e == e) {
        term[i].coef += coef;
        return;
      }
    term[count++] = Term{f, coef, e};
  }
};

// The twelve functions times 12 (Stam 1998's appendix writes them so, in (u, v, w)), by
// their symmetry classes: with X, Y, Z the three barycentric coordinates in any order,
// X^4 + 2 X^3 Y for each ordered pair (the six control points across the triangle's edges'
// far ends), a nine-term quartic symmetric in X and Y for each pair (the three across the
// edges) and a fifteen-term one symmetric in the other two for each coordinate D (the
// triangle's own corners). They sum to 12 (b0 + b1 + b2)^4 = 12.
constexpr Polynomials twelve_times_basis() {
  Polynomials p;
  int f = 0;
  // coef * b_x^px b_y^py b_z^pz
  const auto add = [&](int coef, int x, int px, int y, int py, int z, int pz) {
    std::array<int, 3> e{};
    e[size_t(x)] += px, e[size_t(y)] += py, e[size_t(z)] += pz;
    p.add(f, coef, e);
  };
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y) {
      if (x == y) continue;
      const int z = 3 - x - y;
      add(1, x, 4, y, 0, z, 0), add(2, x, 3, y, 1, z, 0);
      ++f;
    }
  for (int z = 0; z < 3; ++z) {
    const int x = (z + 1) % 3, y = (z + 2) % 3;
    add(1, x, 4, y, 0, z, 0), add(2, x, 3, z, 1, y, 0), add(6, x, 3, y, 1, z, 0), add(6, x, 2, y, 1, z, 1);
    add(12, x, 2, y, 2, z, 0);
    add(1, y, 4, x, 0, z, 0), add(2, y, 3, z, 1, x, 0), add(6, y, 3, x, 1, z, 0), add(6, y, 2, x, 1, z, 1);
    ++f;
  }
  for (int d = 0; d < 3; ++d) {
    const int x = (d + 1) % 3, y = (d + 2) % 3;
    add(1, x, 4, y, 0, d, 0), add(6, x, 3, y, 1, d, 0), add(8, x, 3, d, 1, y, 0), add(36, x, 2, y, 1, d, 1);
    add(24, x, 2, d, 2, y, 0), add(24, x, 1, d, 3, y, 0);
    add(1, y, 4, x, 0, d, 0), add(6, y, 3, x, 1, d, 0), add(8, y, 3, d, 1, x, 0), add(36, y, 2, x, 1, d, 1);
    add(24, y, 2, d, 2, x, 0), add(24, y, 1, d, 3, x, 0);
    add(6, d, 4, x, 0, y, 0), add(60, d, 2, x, 1, y, 1), add(12, x, 2, y, 2, d, 0);
    ++f;
  }
  return p;
}

// d/ds (axis 1) or d/dt (axis 2): b0 = 1 - s - t gives d/ds = d/db1 - d/db0. The
// coefficients stay integers (times 12), so combining like terms is exact.
constexpr Polynomials derivative(const Polynomials& p, size_t axis) {
  Polynomials out;
  out.degree = p.degree - 1;
  for (size_t i = 0; i < p.count; ++i) {
    const Term& t = p.term[i];
    for (const size_t b : {axis, size_t(0)}) {
      if (t.e[b] == 0) continue;
      std::array<int, 3> e = t.e;
      --e[b];
      out.add(t.f, (b == 0 ? -1 : 1) * t.coef * t.e[b], e);
    }
  }
  // Like terms that cancelled are dropped.
  Polynomials kept;
  kept.degree = out.degree;
  for (size_t i = 0; i < out.count; ++i)
    if (out.term[i].coef != 0) kept.term[kept.count++] = out.term[i];
  return kept;
}

constexpr Polynomials divided_by_12(Polynomials p) {
  for (size_t i = 0; i < p.count; ++i) p.term[i].coef /= 12;
  return p;
}

constexpr Polynomials kTimes12 = twelve_times_basis();
constexpr Polynomials kDs12 = derivative(kTimes12, 1), kDt12 = derivative(kTimes12, 2);
constexpr Polynomials kPosition = divided_by_12(kTimes12);
constexpr Polynomials kDs = divided_by_12(kDs12), kDt = divided_by_12(kDt12);
constexpr Polynomials kDss = divided_by_12(derivative(kDs12, 1)), kDst = divided_by_12(derivative(kDs12, 2)),
                      kDtt = divided_by_12(derivative(kDt12, 2));
static_assert(kTimes12.count == 6 * 2 + 3 * 9 + 3 * 15, "each term its own monomial");

// The monomials b0^e0 b1^e1 b2^e2 of the degrees asked for, by (e1, e2).
struct Monomials {
  double m[5][5][5];  // [degree][e1][e2]: only the degrees asked for are set
  Monomials(const Uv& st, int lowest) {
    const double b[3] = {1 - st[0] - st[1], st[0], st[1]};
    double power[3][5];
    for (size_t i = 0; i < 3; ++i) {
      power[i][0] = 1;
      for (size_t k = 1; k < 5; ++k) power[i][k] = power[i][k - 1] * b[i];
    }
    for (int d = lowest; d <= 4; ++d)
      for (int e1 = 0; e1 <= d; ++e1)
        for (int e2 = 0; e1 + e2 <= d; ++e2)
          m[d][e1][e2] = power[0][d - e1 - e2] * power[1][e1] * power[2][e2];
  }
};

// w[f] = the sum of P's terms of f, in P's order from +0: every term a compile-time
// constant times a monomial.
template <const Polynomials& P, size_t... T>
void sum_terms(const Monomials& x, std::array<double, kBoxSplineFunctions>& w, std::index_sequence<T...>) {
  w.fill(0.0);
  ((w[size_t(P.term[T].f)] += P.term[T].coef * x.m[P.degree][P.term[T].e[1]][P.term[T].e[2]]), ...);
}
template <const Polynomials& P>
void sum_terms(const Monomials& x, std::array<double, kBoxSplineFunctions>& w) {
  sum_terms<P>(x, w, std::make_index_sequence<P.count>());
}

}  // namespace

void box_spline_weights(const Uv& st, int count, BoxSplineWeights& w) {
  const Monomials x(st, count >= 6 ? 2 : count >= 3 ? 3 : 4);
  sum_terms<kPosition>(x, w[0]);
  if (count < 3) return;
  sum_terms<kDs>(x, w[1]);
  sum_terms<kDt>(x, w[2]);
  if (count < 6) return;
  sum_terms<kDss>(x, w[3]);
  sum_terms<kDst>(x, w[4]);
  sum_terms<kDtt>(x, w[5]);
}

void box_spline_rows(const BoxSplineLabels& labels, const Uv& st, int count, double* const* out) {
  BoxSplineWeights w;
  box_spline_weights(st, count, w);
  for (size_t n = 0; n < size_t(count); ++n) {
    double* o = out[n];
    std::fill(o, o + labels.labels, 0.0);
    for (size_t f = 0; f < size_t(kBoxSplineFunctions); ++f) o[labels.label[f]] = w[n][f];
  }
}

std::optional<BoxSplineLabels> box_spline_labels(const std::vector<std::vector<double>>& lattice) {
  if (lattice.size() != size_t(kQuarticLattice)) return std::nullopt;
  const size_t L = lattice.front().size();
  if (L < size_t(kBoxSplineFunctions) || L > kFixedLabels) return std::nullopt;
  // The functions' values at the lattice.
  std::array<std::array<double, kBoxSplineFunctions>, kQuarticLattice> reference{};
  for (int q = 0; q < kQuarticLattice; ++q)
    sum_terms<kPosition>(Monomials(quartic_lattice_point(q), 4), reference[size_t(q)]);
  const auto label = lattice_functions<kBoxSplineFunctions>(
      lattice, [&](size_t q, size_t f) { return reference[q][f]; }, 1e-12);
  if (!label) return std::nullopt;
  BoxSplineLabels out;
  out.labels = std::uint8_t(L);
  for (size_t f = 0; f < size_t(kBoxSplineFunctions); ++f) out.label[f] = std::uint8_t((*label)[f]);
  for (size_t f = 0; f < size_t(kBoxSplineFunctions); ++f) out.by_label[f] = std::uint8_t(f);
  std::sort(out.by_label.begin(), out.by_label.end(),
            [&](std::uint8_t a, std::uint8_t b) { return out.label[a] < out.label[b]; });
  return out;
}

}  // namespace subdiv
