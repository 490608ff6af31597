#pragma once
// Two prepared surfaces of one mesh (the shortcuts and the general way, say) must give the
// same bits at (face, u, v): positions and derivatives of every order asked for (0, 1, 2),
// through evaluate() and through evaluate_into() of a sample reused from point to point (and
// from order to order), and the stencil of the given derivative order (samples and stencils
// alike).
#include <doctest/doctest.h>

#include <span>

#include "framework/limit/limit_surface.h"

namespace subdiv::limit_test {

inline void check_same_sample(const LimitSample& x, const LimitSample& y) {
  REQUIRE(x.has_derivatives == y.has_derivatives);
  REQUIRE(x.has_second_derivatives == y.has_second_derivatives);
  CHECK(x.position == y.position);
  CHECK(x.du == y.du);
  CHECK(x.dv == y.dv);
  CHECK(x.duu == y.duu);
  CHECK(x.duv == y.duv);
  CHECK(x.dvv == y.dvv);
}

inline void check_same_bits(const LimitSurface& a, const LimitSurface& b, Index face, double u, double v,
                            std::span<const double> positions, int stencil_derivatives) {
  // Kept across calls: whatever the previous point left in it must not show.
  static thread_local LimitSample reused;
  for (int order = 2; order >= 0; --order) {
    INFO("derivatives " << order);
    const LimitSample x = a.evaluate(face, u, v, positions, 3, order), y = b.evaluate(face, u, v, positions, 3, order);
    check_same_sample(x, y);
    a.evaluate_into(face, u, v, positions, 3, order, reused);
    check_same_sample(reused, x);
    CHECK(reused.steps == x.steps);
    b.evaluate_into(face, u, v, positions, 3, order, reused);
    check_same_sample(reused, y);
    CHECK(reused.steps == y.steps);
  }
  if (stencil_derivatives < 0) return;
  const LimitStencil s = a.stencil(face, u, v, stencil_derivatives), t = b.stencil(face, u, v, stencil_derivatives);
  CHECK(s.vertices == t.vertices);
  CHECK(s.position == t.position);
  CHECK(s.du == t.du);
  CHECK(s.dv == t.dv);
  CHECK(s.duu == t.duu);
  CHECK(s.duv == t.duv);
  CHECK(s.dvv == t.dvv);
}

}  // namespace subdiv::limit_test
