#pragma once
// One-call refinement for tests.
#include <doctest/doctest.h>
#include <utility>

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

// A base level and its positions, as the engine's tests of step_values and the Evaluator
// take them (the level may carry sharpness tags the Mesh has not).
struct LevelCase {
  Level level;
  std::vector<double> positions;
};

inline LevelCase level_case(const Mesh& m) { return {m.level(), m.positions}; }

// `m` with a sharp edge, a semi-sharp edge and a sharp corner (features beside smooth
// vertices, so the kernels, plans and the generic path meet; a tagged level, whose feature
// contexts are classified before any row).
inline LevelCase creased_case(const Mesh& m) {
  LevelCase c = level_case(m);
  c.level.edge_sharpness.assign(size_t(c.level.edge_count()), 0.f);
  c.level.edge_sharpness[0] = 10.f;
  c.level.edge_sharpness[5] = 1.5f;
  c.level.vertex_sharpness.assign(size_t(c.level.vertex_count), 0.f);
  c.level.vertex_sharpness[6] = 3.f;
  return c;
}

inline LevelCase creased_cube_case() { return creased_case(cube()); }

// For each (scheme name, case): the scheme loaded and the case's level refined `levels`
// deep, handed to body(scheme, case, hierarchy, options) with the name captured.
template <class Body>
void for_each_refined_case(const std::vector<std::pair<const char*, LevelCase>>& cases, int levels, Body body) {
  for (const auto& named_case : cases) {
    const char* name = named_case.first;  // not a structured binding: clang 14 cannot capture one in CAPTURE
    CAPTURE(name);
    const auto scheme = load_scheme(name);
    RefineOptions o;
    o.levels = levels;
    const Hierarchy h = refine_topology(*scheme, named_case.second.level, o);
    body(*scheme, named_case.second, h, o);
  }
}

// Weight of source `s` in row `r` (0 when absent).
inline double weight_of(const StencilTable& t, Index r, Index s) {
  for (Index i = t.offsets[r]; i < t.offsets[r + 1]; ++i)
    if (t.indices[i] == s) return t.weights[i];
  return 0.0;
}

}  // namespace subdiv::test
