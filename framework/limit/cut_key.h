#pragma once
// A key of a face's cut read from the mesh itself, without extracting the cut: faces whose
// keys are equal have cuts with one signature (limit_nodes.h), so they share the node and
// only the first of them is cut and signed.
//
// The cut at radius r (extract_neighbourhood, analysis/surface/local_patch.h) is the faces
// with a vertex closer than r. The key labels the mesh around the face breadth-first in
// label_neighbourhood's order (so its labels are the cut's, to the cut's edge) and records
// each of those faces once, when first met — its size, hole flag, corner labels from the
// corner it is met at and its edges' sharpness (boundary edges -1) — and per labelled vertex
// its valence, face count, boundary flag and sharpness. That is the cut with its tags up to
// the labelling, so equal keys mean equal cuts; the signature the nodes use records each
// face from each of its corners and is several times longer.
#include <cstdint>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

struct CutKey {
  std::vector<std::uint32_t> key;
  std::vector<Index> vertices;  // label -> vertex, label_neighbourhood's order
  std::vector<int> distance;    // label -> face-ring distance from the face (sorted)
  // Workspace over the level, cleared entry by entry after each use (a key costs its
  // neighbourhood, not the level).
  std::vector<Index> label_of;
  std::vector<int> entry;
  std::vector<char> face_seen;
  std::vector<Index> faces;

  int count_within(int d) const;  // labels at distance <= d
};

// Labels and keys the neighbourhood of `face` at radius `radius` into `out` (reused).
void key_cut(CutKey& out, const Level& level, Index face, int radius);

}  // namespace subdiv
