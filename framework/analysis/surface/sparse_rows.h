#pragma once
// Limit masks as sparse rows over a level's vertices, and how they travel between levels.
//
// The limit of a vertex is a linear function of the control points: a row of weights.
// The evaluation (limit_evaluation.cpp) finds a vertex's row on whatever level its
// neighbourhood is a known configuration and brings it back to the level asked about,
// through the stencils of the steps in between (child = S parent, so a row r over the
// child's vertices is the row r S over the parent's) and through the vertex numbering of
// an extracted neighbourhood.
#include <span>
#include <utility>
#include <vector>

#include "framework/stencil/stencil_table.h"

namespace subdiv {

using SparseRow = std::vector<std::pair<Index, double>>;  // sorted by vertex, one entry each

// Sorts by vertex and merges repeated vertices.
void normalise_row(SparseRow& row);

// r S: `row` over the rows of `step` (the child vertices) becomes a row over its sources.
SparseRow pull_back(const SparseRow& row, const StencilTable& step);

// Renumbers the vertices: vertex i becomes original[i].
SparseRow renumber(const SparseRow& row, const std::vector<Index>& original);

// sum_i w_i P[i] for `channels` values per vertex.
void apply_row(const SparseRow& row, std::span<const double> points, int channels, std::span<double> out);

}  // namespace subdiv
