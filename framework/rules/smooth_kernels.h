#pragma once
// Smooth kernels: a step's rules for smooth interior elements compiled to flat gathers.
//
// Away from boundaries and features, a rule's new point is a sum over a few roles of its
// element (a vertex: itself, its ring, the new points of its faces and edges; an edge: its
// ends, the new points of its two faces, the vertices opposite it; a face: its corners; a
// face corner: its face's corners from it), each point weighted by the rule's tabulated
// formula (weight_tables.h). Once per step, each element kind's smooth rule is checked
// term by term against those roles; if every term is one of them, the kind's new points
// are computed by reading the roles' points straight off the level's arrays, weights
// looked up per element (once per term when the formula does not vary along the role), and
// every channel accumulated in the same pass, with no row built, planned or interpreted.
// This is what OpenSubdiv's hand-written masks do, for any scheme written as data.
//
// A kind whose rule uses another role (a plugin's, the butterfly's far wings, a curve), C++
// rules (plugins) or per-vertex parameters is not covered; neither is an element on a
// boundary, a feature or non-manifold topology, nor one whose new point the step does not
// make: step_evaluator.cpp builds those rows with the generic interpreter and counts them.
// Values equal the interpreter's rows to round-off (the same terms, summed in role order);
// each element is computed on its own, so any thread count gives the same bits.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "framework/rules/element_rules.h"
#include "framework/rules/step_rows.h"
#include "framework/rules/step_sources.h"

namespace subdiv {

class FlatKernels;

// Hidden: the per-element kernels are member templates, which a shared library would
// otherwise call through the PLT (vague linkage), one call per new point.
class [[gnu::visibility("hidden")]] SmoothKernels {
public:
  SmoothKernels(const StepContext& step, const std::vector<ChildGroup>& groups);
  ~SmoothKernels();

  // Whether `kind`'s smooth rule compiled to a kernel.
  bool covers(Element kind) const { return !kernels_[int(kind)].empty(); }
  // Computes the new points of rows [begin, end) of `kind`'s group into dst (child-major,
  // in.channels values each). Rows whose element is not a smooth interior one are appended
  // to `left` for the generic path; rows whose weights do not sum to 1 are marked in
  // `bad`. Returns how many rows it computed, and in `flat` how many of them by the flat
  // kernels (flat_kernels.h), which take the kinds whose rule has one of their shapes.
  Index run(Element kind, const ChildGroup& group, Index begin, Index end, const StepSources& in, double* dst,
            std::vector<Index>& left, FirstBadRow& bad, Index& flat) const;

  // For repeated evaluation: the flat kernels' neighbourhoods read off the topology once
  // (FlatKernels::resolve_neighbourhoods); the values stay the same bits.
  void resolve_neighbourhoods();

  // How a term gathers its points.
  enum class Gather : std::uint8_t {
    Self,        // vertex: v
    Ring,        // vertex: the other ends of its ring edges
    FacePoints,  // vertex or edge: the new points of its faces
    EdgePoints,  // vertex or face: the new points of its edges
    Ends,        // edge: its two ends
    Opposite,    // edge: in each of its two triangles, the vertex off the edge
    FarWings,    // edge: for each of its triangles, the vertices across the triangle's other two edges
    EndRing0,    // edge: the ring of its first end, counted CCW from the edge
    EndRing1,    // edge: likewise for its second end
    EndSector,   // edge: an end's sector (end_sectors.h): empty at the ends the kernels take, so left out
    Corners,     // face: its corners in order; face corner: its face's corners from it
  };
  struct Term {
    Gather gather;
    const CompiledTerm* weights;
    bool varies;  // the weight depends on the point's place j along the role
    // Most formulas read n or k alone, or nothing: their weight is one load.
    enum class Reads : std::uint8_t { Nothing, N, K, More } reads;
    double weight_at(int n, int k, int j, int n0 = 0, int n1 = 0, int k0 = 0, int k1 = 0) const {
      if (reads == Reads::Nothing) return weights->table[0];
      if (reads == Reads::N) return weights->table[size_t(n) * weights->stride_n];
      if (reads == Reads::K) return weights->table[size_t(k) * weights->stride_k];
      return weights->weight(n, k, j, n0, n1, k0, k1);
    }
    // For an edge's far wings and end rings, whose weights often vanish by the ends'
    // valences (one stencil or another): per (n0, n1), whether every weight of the term is
    // 0 (its points are then not gathered). Empty when the weights read more than n0 and n1.
    std::vector<std::uint8_t> zero_by_ends;
    int max_n = 0;
    // Yes or No from the table; Unknown without one (or beyond it): the kernel then checks.
    enum class Zero : std::uint8_t { Unknown, Yes, No };
    Zero zero_at(int n0, int n1) const {
      if (zero_by_ends.empty() || n0 > max_n || n1 > max_n) return Zero::Unknown;
      return zero_by_ends[size_t(n0) * size_t(max_n + 1) + size_t(n1)] ? Zero::Yes : Zero::No;
    }
  };

private:
  // One element's new point into out and its weight sum; false when the element is not a
  // smooth interior one (out is then undefined). C: the channel count, or 0 for in.channels.
  template <int C>
  bool vertex_point(Index v, const StepSources& in, double* out, double& weight_sum) const;
  template <int C>
  bool edge_point(Index e, const StepSources& in, double* out, double& weight_sum) const;
  template <int C>
  bool face_point(Index f, const StepSources& in, double* out, double& weight_sum) const;
  template <int C>
  bool corner_point(Index f, int corner, const StepSources& in, double* out, double& weight_sum) const;
  template <int C>
  Index run_rows(Element kind, const ChildGroup& group, Index begin, Index end, const StepSources& in, double* dst,
                 std::vector<Index>& left, FirstBadRow& bad) const;
  // The child vertex made for element e of a kind (face or edge) in this step, or kNone.
  Index new_point(Element kind, Index e) const { return groups_[int(kind)].child_of(e); }
  // Adds the new points of `elements` (of `kind`), point j weighted by weight(j), to acc and
  // the weights to sum; false when one of them has no new point in this step.
  template <class Accumulator, class Weight>
  bool add_new_points(Accumulator& acc, double& sum, Element kind, std::span<const Index> elements,
                      const StepSources& in, Weight weight) const;

  const StepContext& step_;
  const std::vector<ChildGroup>& groups_;
  std::vector<Term> kernels_[kElementCount];  // empty: not covered
  bool edge_reads_shape_ = false;  // an edge term reads k, n0, n1, k0, k1 or needs triangles or rings
  // An edge term reads its ends' sectors (end_sectors.h): edges with an end on a boundary or
  // crease are left to the interpreter, elsewhere the sector variables are 0 and the roles empty.
  bool edge_reads_sectors_ = false;
  // The parent level has no sharpness tags: its interior vertices and edges are smooth.
  const bool untagged_;
  std::unique_ptr<FlatKernels> flat_;
};

}  // namespace subdiv
