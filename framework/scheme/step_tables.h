#pragma once
// A scheme step's rules ready for the engine: its rule table compiled (rules/weight_tables.h)
// and the scheme's decisions about boundaries and creases applied — which curve scheme they
// follow, and what smoothing passes do with them.
#include "framework/rules/weight_tables.h"
#include "framework/scheme/scheme.h"

namespace subdiv {

// max_n: the largest valence, max_k: the largest face size on the level; level: l.
// `parameters`: the values formulas see, when not the scheme's own (per-vertex parameters).
// `present`: the level's valences and sector bound, when known (LevelValences).
WeightTables step_weight_tables(const Scheme& scheme, const StepRules& step, int max_n, int max_k, int level,
                                const std::map<std::string, double>* parameters = nullptr,
                                const LevelValences* present = nullptr);

// Whether the scheme can refine boundaries and creases at all: it names a curve scheme (its
// own or a split's), states a crease rule, or has code rules that handle features. Without
// any, a mesh with a boundary, a crease or a face-varying seam is refused at refine time.
bool has_feature_rules(const Scheme& scheme);

}  // namespace subdiv
