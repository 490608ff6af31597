#pragma once
// The weight tables of the evaluator's many small refinements: a cut of a few rings per
// neighbourhood, refined from level 0. Compiling a step's tables (muParser over every
// valence and face size) costs about a millisecond, far more than refining a cut of a few
// hundred faces, so the tables are kept for the whole LimitSurface (engine/weight_table_cache.h)
// instead of compiled again for every cut.
#include <memory>

#include "framework/engine/weight_table_cache.h"

namespace subdiv {

struct Scheme;

// Seeded with the valences along a cut's border (1 to the regular one), which every cut and
// every piece of adaptive refinement has. `level_independent`: no formula of the scheme reads
// the level l (then one table serves every level; the evaluator's cuts all start at level 0).
std::unique_ptr<WeightTableCache> cut_weight_tables(const Scheme& scheme, bool level_independent = false);

}  // namespace subdiv
