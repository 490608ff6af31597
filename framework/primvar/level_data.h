#pragma once
// The user's data carried through a refinement, level by level (OpenSubdiv's "primvars"):
//  - point arrays of doubles are vertex-varying data: refined with the scheme's own rules,
//    packed with the positions into one multi-channel pass (engine/refiner.h step_values:
//    one gather per child, several channels), so they follow the surface exactly as the
//    points do — for every scheme, plugins included;
//  - integer point arrays (ids, labels) cannot be averaged: a vertex point keeps its
//    vertex's value; an edge, face or corner point takes the value its element's vertices
//    share, or the smallest of them where they differ (carry_integer_tuples);
//  - normals are not refined (a mix of unit normals is not a normal): they are left out,
//    and `subdiv refine --normals` writes the exact limit normals instead;
//  - cell arrays follow the faces: a child face takes its parent face's tuple; a face that
//    lies in no single parent face (a dual split's vertex and edge faces) takes the tuple of
//    the parent face of its first corner (inherit_cell_tuples).
#include <span>
#include <string>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/io/mesh_data.h"

namespace subdiv {

struct LevelData {
  std::vector<double> positions;  // xyz per vertex
  std::vector<DataArray> point_data, cell_data;
};

// The arrays a refinement carries: all but normals. The names of the arrays left out are
// appended to `dropped` when given.
std::vector<DataArray> carried_point_arrays(const std::vector<DataArray>& arrays,
                                            std::vector<std::string>* dropped = nullptr);

// Throws subdiv::Error naming the array and the vertex (or face) where a double array holds
// NaN or infinity: refinement would spread it to every neighbour. `source` names the file.
void check_finite_arrays(const LevelData& level, const std::string& source);

// Level `step`'s data carried to level step + 1 of `h` (h from refine_topology with the same
// runs and options). Point arrays must be carried ones (no normals).
LevelData next_level_data(std::span<const SchemeRun> runs, const Hierarchy& h, int step, const LevelData& level,
                          const RefineOptions& options);

// Integer tuples by origin, as described above.
std::vector<double> carry_integer_tuples(const Level& parent, const ChildOrigins& origins,
                                         std::span<const double> values, int components);

// Per child face, its parent face's tuple (see above); faces with no parent face at all get
// NaN (integer arrays: -1).
std::vector<double> inherit_cell_tuples(const Level& parent, const Level& child, const ChildOrigins& origins,
                                        std::span<const double> values, int components, bool integer);

}  // namespace subdiv
