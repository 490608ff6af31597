#include <cmath>
#include <doctest/doctest.h>

#include "framework/util/error.h"
#include "support/refine_helpers.h"

using namespace subdiv;

TEST_CASE("composed stencil tables equal applying the levels one after another") {
  const test::Mesh mesh = test::pyramid();
  auto r = test::refine_mesh(mesh, "catmull-clark", 3);
  const auto& S = r.hierarchy.stencils;
  const StencilTable all = compose(compose(S[0], S[1]), S[2]);
  CHECK(all.source_count == mesh.vertex_count);
  CHECK(all.row_count() == r.hierarchy.levels[3].vertex_count);
  const auto direct = all.apply(mesh.positions, 3);
  for (size_t i = 0; i < direct.size(); ++i) CHECK(direct[i] == doctest::Approx(r.positions[i]).epsilon(1e-13));
}

TEST_CASE("any number of channels: each channel interpolates independently") {
  const test::Mesh mesh = test::cube();
  auto r = test::refine_mesh(mesh, "catmull-clark", 2);
  std::vector<double> five(mesh.vertex_count * 5);
  for (Index v = 0; v < mesh.vertex_count; ++v)
    for (int c = 0; c < 5; ++c) five[5 * v + c] = c < 3 ? mesh.positions[3 * v + c] : v * (c - 2.0);
  const auto out = interpolate(r.hierarchy, 2, five, 5);
  for (size_t v = 0; v < r.positions.size() / 3; ++v)
    for (int c = 0; c < 3; ++c) CHECK(out[5 * v + c] == doctest::Approx(r.positions[3 * v + c]).epsilon(1e-14));
}

TEST_CASE("apply_rows gives the chosen rows of apply, bit for bit, in the order asked") {
  const test::Mesh mesh = test::cube();
  auto r = test::refine_mesh(mesh, "catmull-clark", 2);
  const StencilTable& table = r.hierarchy.stencils[1];
  const Index sources = table.source_count;
  std::vector<Index> rows;  // every third row, backwards, one repeated
  for (Index k = table.row_count() - 1; k >= 0; k -= 3) rows.push_back(k);
  rows.push_back(rows.front());
  for (int channels : {1, 3, 5}) {
    CAPTURE(channels);
    std::vector<double> src(size_t(sources) * size_t(channels));
    for (size_t i = 0; i < src.size(); ++i) src[i] = std::sin(0.7 * double(i)) + 0.1 * double(i % 7);
    const std::vector<double> all = table.apply(src, channels);
    const std::vector<double> some = table.apply_rows(src, rows, channels);
    REQUIRE(some.size() == rows.size() * size_t(channels));
    for (size_t k = 0; k < rows.size(); ++k)
      for (int c = 0; c < channels; ++c)
        CHECK(some[k * size_t(channels) + size_t(c)] == all[size_t(rows[k]) * size_t(channels) + size_t(c)]);
  }
  const std::vector<double> src(size_t(sources) * 3, 1.0);
  const std::vector<Index> outside{table.row_count()};
  CHECK_THROWS_WITH_AS(table.apply_rows(src, outside, 3), doctest::Contains("is not in 0.."), Error);
  CHECK_THROWS_AS(table.apply_rows(std::span<const double>(src).first(3), rows, 3), Error);
}
