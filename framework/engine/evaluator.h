#pragma once
// Repeated evaluation, for animation, interactive editing and fitting: refine the topology
// once (refine_topology), then carry any number of value sets (each frame's positions, or
// any per-vertex data) from the base level to the finest. Every step is made ready once,
// when the Evaluator is built: its weight tables, per-vertex rules, feature contexts,
// child groups, row plans and compiled kernels; an evaluation only computes points, level
// after level, into buffers it keeps. It is what OpenSubdiv's StencilTable::UpdateValues
// is for, without a table to build or store.
//
//   Hierarchy h = refine_topology(scheme, build_level(...), options);
//   Evaluator evaluator(scheme, h, options);
//   for (each frame) evaluator.evaluate(frame_positions, finest_positions, 3);
//
// Values are those of step_values level by level (the same bits), for any thread count.
#include <memory>
#include <span>
#include <vector>

#include "framework/engine/refiner.h"

namespace subdiv {

class Evaluator {
public:
  // `topology` (and the schemes of `runs`) must outlive the evaluator; `options` is copied.
  // Throws subdiv::Error as step_values does (runs that do not match the hierarchy, bad
  // per-vertex parameters, rules that do not sum to one).
  Evaluator(std::span<const SchemeRun> runs, const Hierarchy& topology, const RefineOptions& options);
  Evaluator(const Scheme& scheme, const Hierarchy& topology, const RefineOptions& options);
  ~Evaluator();
  Evaluator(Evaluator&&) noexcept;
  Evaluator& operator=(Evaluator&&) noexcept;

  // Steps from the base level to the finest, and the vertex counts at both ends.
  int levels() const;
  Index base_vertex_count() const;
  Index finest_vertex_count() const;

  // base_values (base vertex count x channels, vertex-major) carried to the finest level,
  // into `finest` (finest vertex count x channels). After the first call with a channel
  // count, a call allocates nothing: the intermediate levels live in two buffers the
  // evaluator keeps. Not to be called concurrently on one evaluator (each level runs in
  // parallel inside).
  void evaluate(std::span<const double> base_values, std::span<double> finest, int channels);
  std::vector<double> evaluate(std::span<const double> base_values, int channels);

private:
  struct Prepared;
  std::unique_ptr<Prepared> prepared_;
};

}  // namespace subdiv
