// The quartic box spline's closed forms (box_spline_patch.h): a partition of unity whose
// values at a corner are the regular vertex's limit mask (1/2 at the vertex, 1/12 at each of
// its six neighbours: Loop 1987; Stam 1998), derivatives that are those of the values
// (central differences), and a patch given at the lattice recognised whatever the order of
// its labels, and refused when it is not the box spline's.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "framework/limit/box_spline_patch.h"
#include "framework/limit/triangle_patch.h"

using namespace subdiv;

namespace {

// The six rows at (s, t) with the functions in their own order (label f = f).
std::array<std::array<double, 16>, 6> rows_at(const BoxSplineLabels& labels, const Uv& st) {
  std::array<std::array<double, 16>, 6> r{};
  double* out[6];
  for (size_t n = 0; n < 6; ++n) out[n] = r[n].data();
  box_spline_rows(labels, st, 6, out);
  return r;
}

BoxSplineLabels identity() {
  BoxSplineLabels l;
  l.labels = kBoxSplineFunctions;
  for (size_t f = 0; f < size_t(kBoxSplineFunctions); ++f) l.label[f] = std::uint8_t(f);
  return l;
}

}  // namespace

TEST_CASE("box spline: a partition of unity with the regular vertex's limit mask at each corner") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 50; ++i) {
    double s = unit(rng), t = unit(rng);
    if (s + t > 1) s = 1 - s, t = 1 - t;
    const auto r = rows_at(identity(), {s, t});
    for (size_t n = 0; n < 6; ++n) {
      const double sum = std::accumulate(r[n].begin(), r[n].begin() + kBoxSplineFunctions, 0.0);
      CHECK(sum == doctest::Approx(n == 0 ? 1.0 : 0.0).epsilon(n < 3 ? 1e-14 : 1e-13));
    }
  }
  for (const Uv corner : {Uv{0, 0}, Uv{1, 0}, Uv{0, 1}}) {
    auto w = rows_at(identity(), corner)[0];
    std::sort(w.begin(), w.begin() + kBoxSplineFunctions);
    for (size_t f = 0; f < 5; ++f) CHECK(w[f] == doctest::Approx(0).epsilon(1e-16));
    for (size_t f = 5; f < 11; ++f) CHECK(w[f] == doctest::Approx(1.0 / 12).epsilon(1e-15));
    CHECK(w[11] == doctest::Approx(0.5).epsilon(1e-15));
  }
}

TEST_CASE("box spline: first and second derivatives are central differences of the values") {
  const double h = 1e-5;
  for (const Uv st : {Uv{0.2, 0.3}, Uv{0.6, 0.1}, Uv{0.05, 0.8}}) {
    const auto r = rows_at(identity(), st);
    const auto ps = rows_at(identity(), {st[0] + h, st[1]}), ms = rows_at(identity(), {st[0] - h, st[1]});
    const auto pt = rows_at(identity(), {st[0], st[1] + h}), mt = rows_at(identity(), {st[0], st[1] - h});
    for (size_t f = 0; f < size_t(kBoxSplineFunctions); ++f) {
      CHECK(r[1][f] == doctest::Approx((ps[0][f] - ms[0][f]) / (2 * h)).epsilon(1e-8));
      CHECK(r[2][f] == doctest::Approx((pt[0][f] - mt[0][f]) / (2 * h)).epsilon(1e-8));
      CHECK(r[3][f] == doctest::Approx((ps[1][f] - ms[1][f]) / (2 * h)).epsilon(1e-8));
      CHECK(r[4][f] == doctest::Approx((pt[1][f] - mt[1][f]) / (2 * h)).epsilon(1e-8));
      CHECK(r[5][f] == doctest::Approx((pt[2][f] - mt[2][f]) / (2 * h)).epsilon(1e-8));
    }
  }
}

TEST_CASE("box spline: a quartic patch is recognised by its values at the lattice, in any label order") {
  // Fourteen labels: the twelve functions in a shuffled order and two labels with zero rows.
  std::vector<size_t> where(14);
  std::iota(where.begin(), where.end(), 0);
  std::shuffle(where.begin(), where.end(), std::mt19937(3));
  std::vector<std::vector<double>> lattice(kQuarticLattice, std::vector<double>(14, 0.0));
  for (int q = 0; q < kQuarticLattice; ++q) {
    const auto r = rows_at(identity(), quartic_lattice_point(q));
    for (size_t f = 0; f < size_t(kBoxSplineFunctions); ++f) lattice[size_t(q)][where[f]] = r[0][f];
  }
  const auto found = box_spline_labels(lattice);
  REQUIRE(found);
  CHECK(found->labels == 14);
  for (size_t f = 0; f < size_t(kBoxSplineFunctions); ++f) CHECK(found->label[f] == where[f]);
  // The patch's points then come from the closed forms, within round-off of the lattice form.
  const PolynomialPatch patch = triangle_patch(lattice);
  REQUIRE(patch.box);
  const CornerRows closed = quartic_rows(patch, {0.3, 0.45}), lagrange = quartic_rows(lattice, {0.3, 0.45});
  for (size_t l = 0; l < 14; ++l) {
    CHECK(closed.position[l] == doctest::Approx(lagrange.position[l]).epsilon(1e-13));
    CHECK(closed.ds[l] == doctest::Approx(lagrange.ds[l]).epsilon(1e-12));
    CHECK(closed.dtt[l] == doctest::Approx(lagrange.dtt[l]).epsilon(1e-11));
  }
  // Not the box spline's: one value off by 1e-9, or a function missing.
  auto off = lattice;
  off[7][where[4]] += 1e-9;
  CHECK_FALSE(box_spline_labels(off));
  CHECK_FALSE(triangle_patch(off).box);
  auto missing = lattice;
  for (auto& row : missing) row[where[0]] = 0;
  CHECK_FALSE(box_spline_labels(missing));
}
