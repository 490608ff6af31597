#include <doctest/doctest.h>

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
