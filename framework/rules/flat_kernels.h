#pragma once
// Flat kernels: the three shapes most smooth rules take, run as straight loops.
//
// The smooth kernels (smooth_kernels.h) run any rule written with their roles, one term at
// a time, each term's weight looked up for the element at hand. Most shipped schemes'
// rules are simpler than that allows, and their shape can be seen once per step:
//
//  - a face point:   w(k) times each corner, plus w'(k) times each edge point
//                    (k the face size);
//  - an edge point:  constant weights on its two ends, the new points of its two faces and
//                    the vertices opposite it in its two triangles;
//  - a vertex point: w_self(n) times itself, w_ring(n) times each ring vertex, w_face(n)
//                    times each face point, w_edge(n) times each edge point (n the valence);
//  - a face corner's point (dual schemes): w(k, j) times the face's corner j places on from
//                    it, plus w_self(k) times the corner itself.
//
// A kind whose compiled terms fit its shape has its weights tabulated per valence or face
// size (summed over terms that gather the same points), and its new points are computed by
// a loop that reads the topology arrays and the points directly, as a hand-written
// subdivision loop would (OpenSubdiv's Far::PrimvarRefiner): no term list, no per-term
// lookup, the row's weight sum checked once per valence instead of once per point. This
// halves the time of the smooth kernels for Catmull-Clark and Loop. Nothing here knows a
// scheme: the shapes are read off the terms.
//
// Elements the loop cannot take (boundaries, features, non-manifold topology, a valence
// or face size beyond the tables) are left to the smooth kernels and the interpreter
// behind them. The values equal the smooth kernels' to round-off (a term's weight is
// applied to each point as there; terms gathering the same points are merged); each point
// is computed on its own, so any thread count gives the same bits.
#include <cstdint>
#include <memory>
#include <vector>

#include "framework/rules/element_rules.h"
#include "framework/rules/step_rows.h"
#include "framework/rules/step_sources.h"
#include "framework/util/scratch_vector.h"

namespace subdiv {

struct CompiledTerm;

class [[gnu::visibility("hidden")]] FlatKernels {
public:
  // What a term of a smooth rule gathers, as far as the flat shapes are concerned.
  enum class Points : std::uint8_t { Self, Ring, FacePoints, EdgePoints, Ends, Opposite, Corners, Other };
  struct TermShape {
    Points points;
    const CompiledTerm* weights;
    bool varies;       // the weight changes along the role (point j); allowed for corners only
    bool reads_shape;  // the weight reads more than the element's own n (or k)
  };

  // terms[kind]: the kind's smooth terms, or empty when the smooth kernels do not cover it.
  FlatKernels(const StepContext& step, const std::vector<ChildGroup>& groups,
              const std::vector<TermShape> (&terms)[kElementCount]);

  bool covers(Element kind) const;
  // Computes rows [begin, end) of `kind`'s group into dst as SmoothKernels::run does
  // (rows it cannot take go to `left`, rows whose weights do not sum to 1 are marked in
  // `bad`) and returns how many it computed. Only for kinds it covers.
  Index run(Element kind, Index begin, Index end, const StepSources& in, double* dst, std::vector<Index>& left,
            FirstBadRow& bad) const;

  // For repeated evaluation (engine/evaluator.h): which vertices and edges the loops take,
  // and the points they gather (a ring's far ends, a triangle pair's opposite vertices),
  // read off the topology once. Each later run reads flat index lists, as a stencil table
  // does, instead of walking rings and triangles and testing each element again
  // (docs/benchmarks.md has the times).
  // The same points are added in the same order: the same bits. Costs one index per ring
  // entry, two or four per edge and a byte per vertex, for the evaluator's lifetime.
  void resolve_neighbourhoods();

private:
  // Weights per valence (vertex) or face size (face), indexed by n; `sum_ok[n]` is false
  // where the row's weights would not sum to 1.
  struct PerSize {
    std::vector<double> self, ring, face_points, edge_points, corners;
    std::vector<std::uint8_t> sum_ok;
    bool uses_ring = false, uses_face_points = false, uses_edge_points = false;
  };
  // Per face size k, the weights of the corners j = 0 .. k-1 places on (at row_start[k]).
  struct CornerWeights {
    std::vector<double> self, around;
    std::vector<Index> row_start;
    std::vector<std::uint8_t> sum_ok;
  };
  struct EdgeWeights {
    double ends = 0, face_points = 0, opposite = 0;
    bool uses_face_points = false, uses_opposite = false, sum_ok = true;
  };

  // What resolve_neighbourhoods keeps. edge_gathers: per edge, `edge_stride` points (its
  // ends, then its opposite vertices when the rule reads them), or kNone first when the
  // loop leaves the edge; ring_ends: the far end of each vertex_edges entry; vertex_taken:
  // whether the loop takes the vertex. Not zero-filled: resolve_neighbourhoods' parallel
  // passes write every entry a run reads.
  struct Resolved {
    int edge_stride = 2;
    ScratchVector<Index> edge_gathers, ring_ends;
    ScratchVector<std::uint8_t> vertex_taken;
  };

  // Whether the loops take vertex v (of valence n) and edge e: smooth interior elements the
  // tables reach (the smooth kernels' vertex_point and edge_point conditions).
  bool takes_vertex(Index v, Index n) const;
  bool takes_edge(Index e) const;

  // How the loops decide which elements they take: each condition tested (Checked); on a
  // manifold level without sharpness tags, the boundary and sizes alone (Plain, the same
  // answers: smooth_vertex and smooth_edge follow from topology there); or read from
  // resolve_neighbourhoods' lists (Resolved).
  enum class Walk : std::uint8_t { Checked, Plain, Resolved };
  template <int C, Walk W>
  Index run_vertices(Index begin, Index end, const StepSources& in, double* dst, std::vector<Index>& left,
                     FirstBadRow& bad) const;
  template <int C, Walk W>
  Index run_edges(Index begin, Index end, const StepSources& in, double* dst, std::vector<Index>& left,
                  FirstBadRow& bad) const;
  template <int C>
  Index run_corners(Index begin, Index end, const StepSources& in, double* dst, std::vector<Index>& left,
                    FirstBadRow& bad) const;
  template <int C>
  Index run_faces(Index begin, Index end, const StepSources& in, double* dst, std::vector<Index>& left,
                  FirstBadRow& bad) const;

  const StepContext& step_;
  const bool untagged_;
  const bool plain_;  // manifold and untagged: Walk::Plain
  // StepContext::stream_output: the kind computed last, whose points no rule of the step reads
  // back, written with streaming stores (the others are read by it, soon).
  bool stream_[kElementCount] = {};
  // The first child of each kind's run (primal splits: element e's new point is first + e),
  // or kNone when the kind's children are not one run over all its elements.
  Index first_child_[kElementCount];
  bool covers_[kElementCount] = {};
  PerSize vertex_, face_;
  EdgeWeights edge_;
  CornerWeights corner_;
  std::unique_ptr<const Resolved> resolved_;  // null until resolve_neighbourhoods
};

}  // namespace subdiv
