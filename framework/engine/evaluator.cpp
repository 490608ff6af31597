#include "framework/engine/evaluator.h"

#include <algorithm>
#include <array>
#include <fmt/format.h>

#include "framework/engine/level_passes.h"
#include "framework/engine/step_preparation.h"
#include "framework/rules/stencil_builder.h"
#include "framework/rules/step_evaluator.h"
#include "framework/util/error.h"
#include "framework/util/scratch_vector.h"

namespace subdiv {
namespace {

// One application of rules to values: a linear step's rows (the split's, or a smoothing
// pass on the new level), or a non-linear step's rule. Held in place on the heap: the
// context refers to the inputs' tables and the rows to the context.
struct Pass {
  int step = 0;  // the hierarchy's step (its parent level)
  Index target_count = 0;
  StepInputs inputs;
  std::unique_ptr<StepContext> context;
  std::unique_ptr<StepEvaluator> rows;
  std::shared_ptr<const DirectStep> direct;

  void apply(const Hierarchy& h, std::span<const double> from, std::span<double> to, int channels, RowPaths* paths) {
    if (rows) return rows->apply(from, to, channels, paths);
    const std::vector<double> values = run_direct_step(*direct, h, step, from, channels);
    std::copy(values.begin(), values.end(), to.begin());
  }
};

bool overlap(std::span<const double> a, std::span<const double> b) {
  return !a.empty() && !b.empty() && a.data() < b.data() + b.size() && b.data() < a.data() + a.size();
}

}  // namespace

struct Evaluator::Prepared {
  Prepared(const Hierarchy& h, const RefineOptions& o) : topology(h), options(o) {}

  // A linear pass's rows made ready, or a non-linear step's rule.
  void add(const LevelPass& from) {
    auto pass = std::make_unique<Pass>();
    pass->step = from.step;
    pass->target_count = from.target_count;
    if (from.nonlinear()) {
      pass->direct = direct_step(*from.scheme, topology, size_t(from.step), from.level, options);
    } else {
      pass->inputs = prepare_step(*from.scheme, *from.rules, *from.parent, from.level, options, *from.parameters,
                                  /*lazy_features=*/true);
      pass->context = std::make_unique<StepContext>(step_context(*from.scheme, *from.rules, pass->inputs, *from.parent,
                                                                 *from.origins, from.features_refined, from.level,
                                                                 options));
      pass->rows = std::make_unique<StepEvaluator>(*pass->context, /*repeated=*/true);
    }
    passes.push_back(std::move(pass));
  }

  // The two buffers the passes but the last write into, alternately, sized once per
  // channel count (not zero-filled: each pass writes every value it makes).
  void size_buffers(int channels) {
    if (buffer_channels == channels) return;
    for (size_t i = 0; i + 1 < passes.size(); ++i) {
      ScratchVector<double>& b = buffers[i % 2];
      b.resize(std::max(b.size(), size_t(passes[i]->target_count) * size_t(channels)));
    }
    buffer_channels = channels;
  }

  const Hierarchy& topology;
  const RefineOptions options;
  std::unique_ptr<LevelPasses> level_passes;  // the identity origins of smoothing passes live here
  std::vector<std::unique_ptr<Pass>> passes;
  ScratchVector<double> buffers[2];
  int buffer_channels = 0;
};

Evaluator::Evaluator(std::span<const SchemeRun> runs, const Hierarchy& h, const RefineOptions& options)
    : prepared_(std::make_unique<Prepared>(h, options)) {
  Prepared& p = *prepared_;
  p.level_passes = std::make_unique<LevelPasses>(runs, h, p.options, 0, int(h.levels.size()) - 1, "Evaluator");
  for (const LevelPass& pass : p.level_passes->all()) p.add(pass);
}

Evaluator::Evaluator(const Scheme& scheme, const Hierarchy& topology, const RefineOptions& options)
    : Evaluator(std::span<const SchemeRun>(std::array{SchemeRun{&scheme, int(topology.levels.size()) - 1}}), topology,
                options) {}

Evaluator::~Evaluator() = default;
Evaluator::Evaluator(Evaluator&&) noexcept = default;
Evaluator& Evaluator::operator=(Evaluator&&) noexcept = default;

int Evaluator::levels() const { return int(prepared_->topology.levels.size()) - 1; }
Index Evaluator::base_vertex_count() const { return prepared_->topology.levels.front().vertex_count; }
Index Evaluator::finest_vertex_count() const { return prepared_->topology.levels.back().vertex_count; }

void Evaluator::evaluate(std::span<const double> base_values, std::span<double> finest, int channels) {
  Prepared& p = *prepared_;
  if (channels < 1) throw Error(fmt::format("Evaluator::evaluate: {} channels; give 1 or more", channels));
  if (base_values.size() != size_t(base_vertex_count()) * size_t(channels))
    throw Error(fmt::format("Evaluator::evaluate: {} base values for {} vertices of {} channels", base_values.size(),
                            base_vertex_count(), channels));
  if (finest.size() != size_t(finest_vertex_count()) * size_t(channels))
    throw Error(fmt::format("Evaluator::evaluate: room for {} values, but the finest level has {} vertices of {} "
                            "channels",
                            finest.size(), finest_vertex_count(), channels));
  if (overlap(base_values, finest))
    throw Error("Evaluator::evaluate: the base values and the output share memory; give separate buffers");
  if (p.passes.empty()) return void(std::copy(base_values.begin(), base_values.end(), finest.begin()));
  p.size_buffers(channels);
  std::span<const double> from = base_values;
  for (size_t i = 0; i < p.passes.size(); ++i) {
    Pass& pass = *p.passes[i];
    const std::span<double> to = i + 1 == p.passes.size()
                                     ? finest
                                     : std::span<double>(p.buffers[i % 2]).first(size_t(pass.target_count) * channels);
    pass.apply(p.topology, from, to, channels, p.options.evaluation.row_paths);
    from = to;
  }
}

std::vector<double> Evaluator::evaluate(std::span<const double> base_values, int channels) {
  std::vector<double> finest(size_t(finest_vertex_count()) * size_t(std::max(channels, 1)));
  evaluate(base_values, finest, channels);
  return finest;
}

}  // namespace subdiv
