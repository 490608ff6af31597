#pragma once
// Which limit operator belongs to a scheme, decided by mathematics rather than by name.
//
// A limit mask l of a stationary scheme is the left eigenvector of eigenvalue 1 of its
// subdivision matrix: l S = l. A candidate mask is accepted for a scheme when it passes
// that test on the very mesh being interpolated: the masks of the vertex points one step
// down, composed with the step's stencils, give back the masks on the mesh (to 1e-12 per
// weight), and the same again one level further down. A vertex point has its parent's
// valence and context, so for rules that repeat with period one or two (sqrt3's split
// alternates between levels) two steps prove it for every level, and the limit point of
// a convergent scheme is then l applied to the control points.
//
// Dual schemes (no vertex points) take dual_limits.h's V-face centroids, checked by their
// own test (every V-face keeps its centroid one step down).
//
// Candidates, in order: the identity (interpolatory schemes), the masks of the scheme's own
// eigen-analysis (analysed_limit.h), then every provider registered with
// register_limit_mask_provider (a plugin's closed forms, say). A scheme none fits (its
// local subdivision matrices have no convergent eigenvector of 1) is refused with each
// candidate's reason.
//
// Sequences "A:k,...,B" (Lin et al. 2015's two-step scheme is "shape step:1, then Catmull-Clark"): the prefix
// runs are applied once and B forever after, so the limit is B's mask on the level after
// the prefix composed with the prefix's stencils (CompositeLimit), read at the base
// vertices' vertex points. Lin et al. 2015's closed form (2) is this composite for its two-step
// sequence (tests/unit/interpolation/shape_two_step_test.cpp checks them against each other).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "framework/interpolation/limit_evaluator.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme_sequence.h"

namespace subdiv {

// A plugin's hook: return an evaluator for `scheme` (or nullptr when the provider has no
// mask for it). Providers are tried after the built-in candidates and checked like them.
using LimitMaskProvider =
    std::function<std::shared_ptr<const LimitEvaluator>(const Scheme& scheme, const FeatureOptions& features)>;
void register_limit_mask_provider(const std::string& name, LimitMaskProvider provider);
std::vector<std::string> limit_mask_provider_names();

struct LimitSelectionOptions {
  FeatureOptions features;
  int first_step = 0;  // as RefineOptions::first_step
  // Per-vertex parameters of the sequence's first runs (RefineOptions::vertex_parameters),
  // e.g. Lin et al. 2015's lambda; the last scheme, applied forever, must not read them per vertex.
  VertexParameters vertex_parameters;
};

struct LimitChoice {
  std::shared_ptr<const LimitEvaluator> evaluator;
  std::string description;  // the mask used and how it was checked
};

// Throws subdiv::Error when no candidate fits, listing why each was refused.
LimitChoice select_limit(const SchemeSequence& sequence, const Level& base, const LimitSelectionOptions& options = {});

// The refinement the interpolated control mesh is shown with: the sequence's runs, with the
// per-vertex parameters.
Hierarchy refine_for_limit(const SchemeSequence& sequence, const Level& base, const LimitSelectionOptions& options);

// Empty when `evaluator` satisfies l S = l for two steps of `scheme` from `level`; else the
// first mismatch (or why the evaluator cannot run there).
std::string invariance_mismatch(const LimitEvaluator& evaluator, const Scheme& scheme, const Level& level,
                                const RefineOptions& options);

// For each base vertex, its vertex point at the hierarchy's finest level. Throws
// subdiv::Error when a step makes no vertex points (dual schemes such as Doo-Sabin).
std::vector<Index> vertex_descendants(const Hierarchy& hierarchy);

// The limit of prefix runs applied once, then `tail` forever: tail's mask on the level after
// the prefix, composed with the prefix's stencils, rows of the base vertices.
class CompositeLimit final : public LimitEvaluator {
public:
  struct Run {
    std::shared_ptr<const Scheme> scheme;
    int levels = 0;
  };
  CompositeLimit(std::vector<Run> prefix, std::shared_ptr<const LimitEvaluator> tail, LimitSelectionOptions options);
  std::string name() const override;

protected:
  StencilTable stencils_at(const Level& level, int step) const override;

private:
  std::vector<Run> prefix_;
  std::shared_ptr<const LimitEvaluator> tail_;
  LimitSelectionOptions options_;
};

}  // namespace subdiv
