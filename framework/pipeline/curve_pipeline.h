#pragma once
// Polylines through a curve scheme, once for every front-end (`subdiv refine` with a curve
// scheme, Python's subdivkit.refine on a mesh of lines): read or take the polylines, load the
// scheme, refuse what would not fit, refine level by level, carry the point arrays by the
// scheme's own stencils (rational weights as homogeneous coordinates, projected in each kept
// level), and describe each kept level. Surfaces go through refine_pipeline.h.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "framework/curve/curve_level.h"
#include "framework/io/mesh_data.h"
#include "framework/pipeline/refine_request.h"
#include "framework/scheme/scheme.h"

namespace subdiv {

struct CurveRefineRequest {
  // The polylines: read from `mesh_file` when it is given, otherwise `mesh` (its lines,
  // positions and point arrays; a mesh with faces is refused: it needs a surface scheme).
  std::string mesh_file;
  MeshData mesh;
  std::string mesh_name;  // names the mesh in messages
  SchemeSource scheme;    // a curve scheme's name, path or JSON text
  int levels = 1;
  // The point array of rational weights (rational_weights.h); empty: OBJ's fourth
  // coordinate or an array named "weight", if any.
  std::string weights_array;
  bool keep_all_levels = true;  // false: the finest level only
  double memory_budget = 0;     // bytes; 0: what the machine lets this process have
  std::function<void(const std::string& phase)> progress;  // told each level as it starts
};

struct RefinedCurveLevel {
  int level = 0;
  CurveLevel topology;
  // Positions (projected when rational), the polylines (closed ones repeat their first
  // vertex), and the point arrays carried to this level.
  MeshData mesh;
  // The rule that made each point (CurveOrigins::rule: r >= 0 the scheme's rule r, -1 - e
  // end rule e); all 0 on level 0, empty for a non-linear scheme (no rules to name).
  std::vector<std::int8_t> rules;
};

struct CurveRefineResult {
  std::shared_ptr<const CurveScheme> scheme;
  std::vector<RefinedCurveLevel> levels;   // the kept levels, coarsest first
  // Arrays not carried, one sentence each: cell arrays (polylines have no faces), and every
  // array for a non-linear scheme (no rule to carry them by).
  std::vector<std::string> notes;
};

// Throws subdiv::Error naming the mesh or the scheme, or subdiv::OptionError naming an
// option with a placeholder (option_spelling.h).
CurveRefineResult refine_curve_request(CurveRefineRequest request);

// SubdivKit's arrays describing a refined polyline level, as the surface levels have theirs
// (level_description.h): point "rule" (linear schemes) and "level"; cell "polyline" (its
// number in the input) and "closed". A point array of the level's own with one of these
// names is kept instead, and left out here.
struct CurveLevelDescription {
  std::vector<DataArray> point_data, cell_data;
};
CurveLevelDescription describe_curve_level(const RefinedCurveLevel& level);

// Refuses, with the numbers, `levels` steps of arity `arity` from `base` that would not fit
// in memory (or in `budget` bytes when positive) or in 32-bit indices.
void check_curve_size(const CurveLevel& base, int arity, int levels, double budget = 0);

}  // namespace subdiv
