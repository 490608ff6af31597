#pragma once
// Scheme parameters given per vertex (a parameter declared "per_vertex": true, e.g. Lin
// et al. 2015's shape parameter lambda): the values are checked against every scheme of the run
// that declares them, carried down the levels, and turned into one weight table per
// distinct value for the vertex rules of a step (rules/step_rows.h: PerVertexTables).
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/refine/child_origins.h"
#include "framework/rules/step_rows.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_run.h"
#include "framework/topology/level.h"

namespace subdiv {

// Throws subdiv::Error unless every name is a per-vertex parameter of a scheme in `runs`,
// has one finite value per base vertex, and each value lies in the range of every scheme
// that declares it (the message names the vertex).
void check_vertex_parameters(std::span<const SchemeRun> runs, const Level& base, const VertexParameters& values);

// The values on the child level of one step: a vertex point keeps its vertex's value, an
// edge point takes the mean of the edge's ends, a face point the mean of the face's
// vertices, a corner point (dual splits) its corner vertex's value — linear, like
// OpenSubdiv's "varying" data.
VertexParameters carry_vertex_parameters(const Level& parent, const ChildOrigins& origins,
                                         const VertexParameters& values);

// The vertex rules of `step` with the scheme's per-vertex parameters set vertex by vertex:
// one table per distinct combination of values on `parent`. Null when the scheme declares
// none of the given parameters (every vertex then uses the ordinary tables).
std::unique_ptr<PerVertexTables> per_vertex_tables(const Scheme& scheme, const StepRules& step, const Level& parent,
                                                   const VertexParameters& values, int max_n, int max_k, int level);

}  // namespace subdiv
