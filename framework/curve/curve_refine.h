#pragma once
// Refining polylines and closed polygons with a curve scheme: split by the arity, one
// stencil row per new point from the scheme's rules, end rules at open ends. Topology and
// stencils are built once; positions (or any per-point data) are carried through the
// StencilTables, one product per level or one in total with compose().
//
// New points of one step (parent polyline of N points, arity m, rule r of old point i):
//   closed:  all m N points m*i + r, indices taken modulo N;
//   open, ends "uniform":  the points m*i + r whose rule reads old points 0..N-1 only;
//   open, ends "interpolate" or explicit end rules:  the points m*i + r that sit inside
//     the polyline (0 <= i + offset_r <= N - 1, offset_r as in CurveRulesAtLevel), in order;
//     if the first of them does not sit on old point 0 (dual schemes such as Chaikin), a
//     new end point is put before it, likewise after the last. End rule e then gives the
//     e-th point from each end (e = 0: the end point; "interpolate" has the one rule {1}).
//     Old points beyond an end that a rule reads are extrapolated linearly:
//     P_{-d} = P_0 + d (P_0 - P_1), P_{N-1+d} = P_{N-1} + d (P_{N-1} - P_{N-2}).
// An end point that copies its parent (weight 1) is shared by every polyline ending there,
// so polylines that meet at their ends stay joined.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "framework/curve/curve_level.h"
#include "framework/curve/curve_rules.h"
#include "framework/scheme/scheme.h"
#include "framework/stencil/stencil_table.h"

namespace subdiv {

// How each new point was made: rule >= 0 is the scheme's rule r applied at old point
// `index` (the parent polyline's local index i); rule < 0 is end rule -1 - rule, and
// `index` is 0 at the start of the polyline, 1 at its end.
struct CurveOrigins {
  std::vector<std::int8_t> rule;
  std::vector<Index> index;
};

struct CurveStep {
  CurveLevel child;
  StencilTable stencils;  // child points over parent points
  CurveOrigins origins;
};

// One step. `scheme_name` names the scheme in messages. Throws subdiv::Error when an open
// polyline is too short for the end rules or shrinks below 2 points ("uniform").
CurveStep refine_curve_step(const CurveLevel& parent, const CurveRulesAtLevel& rules,
                            const std::string& scheme_name);

struct CurveHierarchy {
  std::vector<CurveLevel> levels;      // levels[0] is the input
  std::vector<StencilTable> stencils;  // stencils[l]: level l values to level l + 1
  std::vector<CurveOrigins> origins;   // origins[l] describes levels[l + 1]
};

// `levels` steps, the rules evaluated at each level (non-stationary schemes change).
CurveHierarchy refine_curves(const CurveScheme& scheme, CurveLevel base, int levels);

}  // namespace subdiv
