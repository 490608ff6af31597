#pragma once
// The eigen-analysis of a surface scheme at a list of valences, as every front-end asks for
// it (`subdiv analyze`, Python's subdivkit.analyze, ParaView's "SubdivKit Analyze"): the
// valences checked, the centre chosen (a vertex, or a face for dual schemes), one local
// analysis per valence (framework/analysis/surface/surface_analysis.h). Reporting it as a
// table, JSON, dicts or polydata is the front-ends' part.
#include <memory>
#include <vector>

#include "framework/analysis/surface/surface_analysis.h"
#include "framework/scheme/scheme.h"

namespace subdiv {

struct ValenceAnalysisRequest {
  std::shared_ptr<const Scheme> scheme;
  std::vector<int> valences;
  // At boundary vertices (n ring edges, n - 1 faces; valence 2 up) instead of interior ones.
  // A dual scheme is analysed at the face the boundary vertex's faces become.
  bool boundary = false;
  int level = 0;  // the level whose weights a non-stationary scheme is analysed with
  SurfaceAnalysisOptions options;
  // At crease vertices (n ring edges, infinitely sharp at ring edges 0 and n / 2) instead of
  // interior ones; a dual scheme at the face of the first side's sector.
  // (Last, so that the front-ends' positional initialisers stay valid.)
  bool crease = false;
  // At corner vertices (n >= 3 ring edges, infinitely sharp at ring edges 0, n / 3 and
  // 2n / 3: three sectors), each sector judged as at a boundary. Not for dual schemes, whose
  // corner points collapse into one.
  bool corner = false;
};

// Valences analysed at most: the local matrix of valence n has O(n) rows per ring (above
// kMaxDenseValence only interior centres, whose matrix splits by the sector rotation).
inline constexpr int kMaxAnalysedValence = kMaxPatchValence;

// One analysis per valence, in the request's order. Throws OptionError for an empty list, a
// valence outside 2..kMaxAnalysedValence (3.. for corners), or more than one of boundary,
// crease and corner in one request. A scheme that fails the analysis at a valence is no error: the reason is in
// that analysis's verdict.
std::vector<SurfaceAnalysis> analyse_valences(const ValenceAnalysisRequest& request);

}  // namespace subdiv
