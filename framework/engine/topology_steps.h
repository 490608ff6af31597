#pragma once
// Topology one level at a time, for a caller that makes each level's values right after its
// topology and releases the coarser levels as it goes (pipeline/refine_pipeline.cpp), rather
// than refine_topology's whole hierarchy before any value (at level 3 of a 1M-quad mesh,
// 4.8 GB before the first point). The levels and origins are refine_topology's.
#include <span>
#include <vector>

#include "framework/engine/refiner.h"

namespace subdiv {

// The base level with its topological tags: refine_topology's first level.
Hierarchy start_topology(Level base, const RefineOptions& options);

// Adds the next level (h.levels.size()) of `runs`, as refine_topology makes it. Per-vertex
// parameters (RefineOptions::vertex_parameters) are not carried: their caller takes
// refine_topology. With `faces_later`, a faces-only last level of the quad or triangle split
// (without holes) gets its vertex count and origins now and its faces from
// add_deferred_faces: its values read the parent level and the origins, never the child's
// faces, so the faces (1.28 GB at level 3 of a 1M-quad mesh) can wait until the values are
// made and the parent's rings and edges are gone; so do its origins' parent faces. Returns whether the faces were deferred.
bool refine_next_level(std::span<const SchemeRun> runs, Hierarchy& h, const RefineOptions& options, bool faces_later);

// The number of faces a last level with deferred faces will have.
Index deferred_face_count(std::span<const SchemeRun> runs, const Hierarchy& h);

// The faces of a last level made with deferred faces, and its origins' parent faces. Reads
// the parent's face_offsets, face_vertices, face_edges, vertex count and edge_vertices (its
// edge count) only.
void add_deferred_faces(std::span<const SchemeRun> runs, Hierarchy& h);

// `runs` cut to the levels `h` has so far: what step_values takes with a growing hierarchy.
std::vector<SchemeRun> runs_made(std::span<const SchemeRun> runs, const Hierarchy& h);

}  // namespace subdiv
