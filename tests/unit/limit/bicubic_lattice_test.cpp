// A degree-4 tensor patch given at its lattice (tensor_patch.h) recognised as the uniform
// bicubic B-spline patch (de Boor; Stam 1998 section 3) whatever the order of its labels and
// with labels of zero rows among them, its closed form then the lattice form's polynomial;
// and refused when a label's rows are not one B-spline function's.
#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "framework/limit/bspline_patch.h"
#include "framework/limit/tensor_patch.h"

using namespace subdiv;

namespace {

// The B-spline patch's rows at the lattice over `labels` labels, function k at label at[k].
std::vector<std::vector<double>> bspline_lattice(const std::array<Index, 16>& at, size_t labels) {
  std::vector<std::vector<double>> rows;
  for (int q = 0; q < kTensorLattice; ++q) rows.push_back(bspline_rows(at, tensor_lattice_point(q), Index(labels)).position);
  return rows;
}

}  // namespace

TEST_CASE("bicubic lattice: a B-spline patch's lattice rows give back its control points' labels") {
  std::mt19937 rng(11);
  for (int round = 0; round < 20; ++round) {
    // 16 of 20 labels, shuffled; the other four rows zero.
    std::vector<Index> labels(20);
    std::iota(labels.begin(), labels.end(), 0);
    std::shuffle(labels.begin(), labels.end(), rng);
    std::array<Index, 16> at{};
    std::copy_n(labels.begin(), 16, at.begin());
    const auto lattice = bspline_lattice(at, 20);
    const auto found = bicubic_lattice_labels(lattice);
    REQUIRE(found);
    CHECK(found->grid == at);
    for (size_t l = 0; l < 16; ++l) {
      CHECK(found->grid[found->cell[l]] == found->label[l]);
      if (l > 0) CHECK(found->label[l - 1] < found->label[l]);
    }
    // The closed form is the lattice form's polynomial (position and first derivatives).
    std::uniform_real_distribution<double> unit(0, 1);
    const Uv st{unit(rng), unit(rng)};
    const CornerRows a = tensor_rows(lattice, st, 1), b = bspline_rows(found->grid, st, 20);
    for (size_t l = 0; l < 20; ++l) {
      CHECK(a.position[l] == doctest::Approx(b.position[l]).epsilon(1e-12));
      CHECK(a.ds[l] == doctest::Approx(b.ds[l]).epsilon(1e-11));
      CHECK(a.dt[l] == doctest::Approx(b.dt[l]).epsilon(1e-11));
    }
  }
}

TEST_CASE("bicubic lattice: refused when a label is not one B-spline function") {
  std::array<Index, 16> at{};
  std::iota(at.begin(), at.end(), 0);
  auto lattice = bspline_lattice(at, 16);
  REQUIRE(bicubic_lattice_labels(lattice));
  SUBCASE("two functions on one label (a phantom point's combination)") {
    for (auto& row : lattice) row[0] += row[1], row[1] = 0;
    CHECK_FALSE(bicubic_lattice_labels(lattice));
  }
  SUBCASE("a value off by 1e-9") {
    lattice[12][5] += 1e-9;
    CHECK_FALSE(bicubic_lattice_labels(lattice));
  }
  SUBCASE("a function missing") {
    for (auto& row : lattice) row[7] = 0;
    CHECK_FALSE(bicubic_lattice_labels(lattice));
  }
  SUBCASE("a lattice of another size") {
    lattice.pop_back();
    CHECK_FALSE(bicubic_lattice_labels(lattice));
  }
}
