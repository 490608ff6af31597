#pragma once
// --limit and --normals: the finest level's limit normals as point arrays, and with --limit
// its positions and double point arrays moved to their limits with the same masks
// (framework/analysis/surface/limit_evaluation.h); the scheme that would refine it next
// decides. Shared by `subdiv refine` and the ParaView plugin's "Limit positions".
#include <vector>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/engine/refiner.h"
#include "framework/primvar/level_data.h"
#include "framework/scheme/scheme_sequence.h"

namespace subdiv {

struct LimitArrays {
  std::vector<DataArray> point_data;  // "normal" (the role Normals), "limit_exact", "normal_exact"
  LimitResult result;                 // counts and reasons of what was approximated
  std::vector<std::string> warnings;  // the normals left out (below)
};

// A scheme that is not C1 where the mesh is regular (SchemeLimits::regular_not_c1) has no
// limit normals: with move_to_limit the positions are moved and the normal arrays left out
// with a warning; without (normals alone were asked for) an OptionError naming {normals},
// its message starting with `mesh_name` as the pipeline's other refusals of a mesh do.
// `finest` is level h.levels.back()'s data; with move_to_limit its positions and double point
// arrays are replaced by their limits. With `weights` (the name of finest's rational weights,
// rational_weights.h) the limits are those of the rational surface: the masks applied to
// (w·p, w), the position projected, the tangents by the quotient rule.
LimitArrays limit_arrays(const SchemeSequence& seq, const Hierarchy& h, const RefineOptions& options,
                         LevelData& finest, bool move_to_limit, const std::string& mesh_name,
                         const std::string& weights = {});

}  // namespace subdiv
