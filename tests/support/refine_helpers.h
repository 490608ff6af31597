#pragma once
// One-call refinement for tests.
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"

namespace subdiv::test {

struct Refined {
  Hierarchy hierarchy;
  std::vector<double> positions;  // at the finest level
};

inline Refined refine_mesh(const Mesh& mesh, const std::string& scheme, int levels,
                           RefineOptions options = {}, const ParameterOverrides& params = {}) {
  auto s = load_scheme(scheme, params);
  options.levels = levels;
  Refined r{refine(*s, mesh.level(), options), {}};
  r.positions = interpolate(r.hierarchy, levels, mesh.positions, 3);
  return r;
}

// Weight of source `s` in row `r` (0 when absent).
inline double weight_of(const StencilTable& t, Index r, Index s) {
  for (Index i = t.offsets[r]; i < t.offsets[r + 1]; ++i)
    if (t.indices[i] == s) return t.weights[i];
  return 0.0;
}

}  // namespace subdiv::test
