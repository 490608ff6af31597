#include "framework/interpolation/limit_selection.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <mutex>

#include "framework/interpolation/analysed_limit.h"
#include "framework/interpolation/dual_limits.h"
#include "framework/interpolation/interpolatory_limit.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/topology/non_manifold_place.h"
#include "framework/util/error.h"
#include "framework/util/option_spelling.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

constexpr double kMaskTolerance = 1e-12;

struct Registry {
  std::mutex mutex;
  std::vector<std::pair<std::string, LimitMaskProvider>> providers;
};
Registry& registry() {
  static Registry r;
  return r;
}

// The options of a refinement from the base mesh (with the per-vertex parameters) or, with
// from_base false, from a level further down (which the base's values do not fit).
RefineOptions refine_options(const LimitSelectionOptions& o, int levels, int first_step, bool from_base) {
  RefineOptions r;
  r.levels = levels;
  r.features = o.features;
  r.first_step = first_step;
  if (from_base) r.vertex_parameters = o.vertex_parameters;
  return r;
}

std::vector<std::pair<Index, double>> sorted_row(const StencilTable& t, Index r) {
  std::vector<std::pair<Index, double>> row;
  for (Index i = t.offsets[r]; i < t.offsets[r + 1]; ++i) row.emplace_back(t.indices[i], t.weights[i]);
  std::sort(row.begin(), row.end());
  // Merge repeats (compose keeps each source once, but be safe).
  std::vector<std::pair<Index, double>> merged;
  for (const auto& [s, w] : row) {
    if (!merged.empty() && merged.back().first == s) merged.back().second += w;
    else merged.emplace_back(s, w);
  }
  return merged;
}

// Empty when rows agree to kMaskTolerance; else the first source that differs.
std::string row_mismatch(const StencilTable& a, Index ra, const StencilTable& b, Index rb) {
  const auto x = sorted_row(a, ra), y = sorted_row(b, rb);
  size_t i = 0, j = 0;
  while (i < x.size() || j < y.size()) {
    Index s;
    double wa = 0, wb = 0;
    if (j == y.size() || (i < x.size() && x[i].first < y[j].first)) s = x[i].first, wa = x[i++].second;
    else if (i == x.size() || y[j].first < x[i].first) s = y[j].first, wb = y[j++].second;
    else s = x[i].first, wa = x[i++].second, wb = y[j++].second;
    if (std::abs(wa - wb) > kMaskTolerance)
      return fmt::format("the weight of vertex {} is {:.15g} here but {:.15g} after one step", s, wa, wb);
  }
  return {};
}

// Rows `rows[i]` of `t`, in that order.
StencilTable select_rows(const StencilTable& t, const std::vector<Index>& rows) {
  StencilTable out;
  out.source_count = t.source_count;
  for (Index r : rows) {
    out.indices.insert(out.indices.end(), t.indices.begin() + t.offsets[r], t.indices.begin() + t.offsets[r + 1]);
    out.weights.insert(out.weights.end(), t.weights.begin() + t.offsets[r], t.weights.begin() + t.offsets[r + 1]);
    out.offsets.push_back(Index(out.indices.size()));
  }
  return out;
}

std::vector<SchemeRun> as_runs(const std::vector<CompositeLimit::Run>& prefix) {
  std::vector<SchemeRun> runs;
  for (const auto& r : prefix) runs.push_back({r.scheme.get(), r.levels});
  return runs;
}

Hierarchy refine_prefix(const std::vector<CompositeLimit::Run>& prefix, const Level& level,
                        const LimitSelectionOptions& o, int step) {
  const auto runs = as_runs(prefix);
  return refine(runs, level, refine_options(o, 0, step, !prefix.empty()));
}

// Per-vertex parameters shape the prefix only: the tail's mask comes from its
// eigen-analysis at one value of each parameter, which per-vertex values would break.
void check_vertex_parameters_in_prefix(const SchemeSequence& seq, const LimitSelectionOptions& o) {
  const Scheme& tail = *seq.schemes.back();
  for (const auto& [name, values] : o.vertex_parameters) {
    for (const ParameterSpec& p : tail.parameters)
      if (p.name == name && p.per_vertex)
        throw OptionError(fmt::format("per-vertex parameter {}: {} is applied forever (the last scheme of the sequence), "
                                "and limit masks are known for one value of {} only; give it per vertex to a first "
                                "run (e.g. {}:1,...) or give one value with {{param}}", subdiv::quoted(name), subdiv::quoted(tail.name), subdiv::quoted(name), tail.name));
    if (seq.runs.size() < 2)
      throw Error(fmt::format("per-vertex parameter {}: the sequence has no first run that reads it (a sequence "
                              "SHAPE:1,REPEAT)", subdiv::quoted(name)));
  }
}

// The identity first (cheap, and exact for interpolatory schemes), then the scheme's own
// eigen-analysis, then what plugins registered.
std::vector<std::shared_ptr<const LimitEvaluator>> candidates(const std::shared_ptr<const Scheme>& scheme,
                                                              const FeatureOptions& f) {
  std::vector<std::shared_ptr<const LimitEvaluator>> c{std::make_shared<InterpolatoryLimit>(),
                                                       std::make_shared<AnalysedLimit>(scheme, f)};
  std::vector<std::pair<std::string, LimitMaskProvider>> providers;
  {
    std::lock_guard lock(registry().mutex);
    providers = registry().providers;
  }
  for (const auto& [name, provider] : providers)
    if (auto e = provider(*scheme, f)) c.push_back(std::move(e));
  return c;
}

}  // namespace

void register_limit_mask_provider(const std::string& name, LimitMaskProvider provider) {
  std::lock_guard lock(registry().mutex);
  registry().providers.emplace_back(name, std::move(provider));
}

std::vector<std::string> limit_mask_provider_names() {
  std::lock_guard lock(registry().mutex);
  std::vector<std::string> names;
  for (const auto& p : registry().providers) names.push_back(p.first);
  return names;
}

std::vector<Index> vertex_descendants(const Hierarchy& h) {
  const Index base_count = h.levels.front().vertex_count;
  std::vector<Index> at(static_cast<size_t>(base_count));
  for (Index v = 0; v < base_count; ++v) at[v] = v;
  for (size_t l = 0; l < h.origins.size(); ++l) {
    const ChildOrigins& o = h.origins[l];
    std::vector<Index> child_of(size_t(h.levels[l].vertex_count), kNone);
    for (size_t c = 0; c < o.kind.size(); ++c)
      if (o.kind[c] == OriginKind::Vertex) child_of[o.parent[c]] = Index(c);
    for (Index v = 0; v < base_count; ++v) {
      at[v] = child_of[at[v]];
      if (at[v] == kNone)
        throw Error(fmt::format("refinement step {} makes no vertex point for base vertex {} (a dual split)", l + 1,
                                v));
    }
  }
  return at;
}

namespace {

// l S = l on one refinement step `h` (levels[0] -> levels[1]) of `scheme`.
std::string step_mismatch(const LimitEvaluator& evaluator, const Scheme& scheme, const Hierarchy& h,
                          const std::vector<Index>& children, int step) {
  const Level& level = h.levels[0];
  StencilTable here, below;
  try {
    here = evaluator.limit_stencils(level, step);
    below = evaluator.limit_stencils(h.levels[1], step + 1);
  } catch (const Error& e) {
    return e.what();
  }
  const StencilTable after = compose(h.stencils[0], select_rows(below, children));
  for (Index v = 0; v < level.vertex_count; ++v)
    if (auto why = row_mismatch(here, v, after, v); !why.empty())
      return fmt::format("not invariant under step {} of {} (l S != l) at {}vertex {} of valence {}: {}", step + 1,
                         subdiv::quoted(scheme.name), step > 0 ? "refined " : "", v, level.valence(v), why);
  return {};
}

// The two steps the invariance is checked on. Two, not one: a split may alternate between
// levels (sqrt3 trisects boundaries only every other step, Kobbelt 2000), so a mask that
// survives one step can fail the next. Rules that depend on the level in other ways are
// non-stationary and have no fixed mask at all.
struct CheckSteps {
  Hierarchy first, second;
  std::vector<Index> first_children, second_children;  // empty: a dual split
};

CheckSteps check_steps(const Scheme& scheme, const Level& level, const RefineOptions& options) {
  RefineOptions one = options;
  one.levels = 1;
  CheckSteps c;
  c.first = refine(scheme, level, one);
  try {
    c.first_children = vertex_descendants(c.first);
  } catch (const Error&) {
    return c;
  }
  one.first_step = options.first_step + 1;
  c.second = refine(scheme, c.first.levels[1], one);
  c.second_children = vertex_descendants(c.second);
  return c;
}

// What to give `subdiv analyze` to find this scheme: its name when the name finds this very
// file (or it has no file), else the file's path.
std::string analyze_argument(const Scheme& scheme) {
  if (scheme.path.empty() || std::filesystem::path(scheme.path).extension() != ".json") return scheme.name;
  try {
    if (std::filesystem::equivalent(scheme_file_path(scheme.name), scheme.path)) return scheme.name;
  } catch (const std::exception&) {
    // The name finds no file: a user's scheme, known by its path only.
  }
  return scheme.path;
}

std::string two_step_mismatch(const LimitEvaluator& evaluator, const Scheme& scheme, const CheckSteps& c, int step) {
  std::string why = step_mismatch(evaluator, scheme, c.first, c.first_children, step);
  if (why.empty()) why = step_mismatch(evaluator, scheme, c.second, c.second_children, step + 1);
  return why;
}

}  // namespace

std::string invariance_mismatch(const LimitEvaluator& evaluator, const Scheme& scheme, const Level& level,
                                const RefineOptions& options) {
  CheckSteps c;
  try {
    c = check_steps(scheme, level, options);
  } catch (const Error& e) {
    return e.what();
  }
  if (c.first_children.empty())
    return fmt::format("{} makes no vertex points (a dual split), so it has no vertex limit masks", subdiv::quoted(scheme.name));
  return two_step_mismatch(evaluator, scheme, c, options.first_step);
}

CompositeLimit::CompositeLimit(std::vector<Run> prefix, std::shared_ptr<const LimitEvaluator> tail,
                               LimitSelectionOptions options)
    : prefix_(std::move(prefix)), tail_(std::move(tail)), options_(std::move(options)) {}

std::string CompositeLimit::name() const {
  std::string runs;
  for (const auto& r : prefix_) runs += fmt::format("{}{}:{}", runs.empty() ? "" : ",", r.scheme->name, r.levels);
  std::string per_vertex;
  for (const auto& [name, values] : options_.vertex_parameters) per_vertex += fmt::format(", {} per vertex", name);
  return fmt::format("{} after {}{}", tail_->name(), runs, per_vertex);
}

StencilTable CompositeLimit::stencils_at(const Level& level, int step) const {
  const Hierarchy h = refine_prefix(prefix_, level, options_, step);
  const StencilTable tail = tail_->limit_stencils(h.levels.back(), step + int(h.stencils.size()));
  StencilTable rows = select_rows(tail, vertex_descendants(h));
  for (size_t l = h.stencils.size(); l-- > 0;) rows = compose(h.stencils[l], rows);
  return rows;
}

Hierarchy refine_for_limit(const SchemeSequence& seq, const Level& base, const LimitSelectionOptions& o) {
  return refine(seq.runs, base, refine_options(o, 0, o.first_step, true));
}

LimitChoice select_limit(const SchemeSequence& seq, const Level& base, const LimitSelectionOptions& o) {
  if (seq.runs.empty()) throw Error("no scheme given");
  std::vector<CompositeLimit::Run> prefix;
  int prefix_levels = 0;
  for (size_t i = 0; i + 1 < seq.runs.size(); ++i)
    if (seq.runs[i].levels > 0) {
      prefix.push_back({seq.schemes[i], seq.runs[i].levels});
      prefix_levels += seq.runs[i].levels;
    }
  if (!o.vertex_parameters.empty()) check_vertex_parameters_in_prefix(seq, o);
  const Scheme& tail = *seq.schemes.back();

  // The tail's mask on the level after the prefix, checked there.
  const Hierarchy h = refine_prefix(prefix, base, o, o.first_step);
  const Level& level = h.levels.back();
  const int tail_step = o.first_step + prefix_levels;
  const RefineOptions step = refine_options(o, 1, tail_step, false);
  const CheckSteps check = check_steps(tail, level, step);
  std::shared_ptr<const LimitEvaluator> tail_mask;
  std::vector<std::string> refused;
  if (check.first_children.empty()) {
    // A dual scheme: no vertex points, but V-faces whose centroids may be limit points.
    auto dual = std::make_shared<DualCentroidLimit>(seq.schemes.back(), step);
    std::string why = dual_centroid_mismatch(tail, level, step);
    if (why.empty()) {
      try {
        (void)dual->limit_stencils(level, tail_step);
      } catch (const Error& refused_here) {
        why = refused_here.what();
      }
    }
    if (!why.empty()) {
      const std::string prefix = dual->name() + ": ";
      if (why.rfind(prefix, 0) == 0) why.erase(0, prefix.size());
      throw Error(fmt::format("scheme {} is dual (its steps make no vertex points), so a control vertex's limit "
                              "point is the centroid of its V-face; but {}", subdiv::quoted(tail.name), why));
    }
    tail_mask = dual;
  }
  // Schemes with vertex points.
  if (!tail_mask) {
    for (auto& candidate : candidates(seq.schemes.back(), o.features)) {
      std::string why = two_step_mismatch(*candidate, tail, check, tail_step);
      if (why.empty()) {
        tail_mask = candidate;
        break;
      }
      const std::string name = candidate->name();
      refused.push_back(why.rfind(name, 0) == 0 ? why : fmt::format("{}: {}", name, why));
    }
  }
  if (!tail_mask) {
    std::string list;
    for (const auto& r : refused) list += "\n  - " + r;
    const auto providers = limit_mask_provider_names();
    // A non-manifold vertex has no limit mask at all: the eigenvalues are not the story, the
    // place is (the first non-manifold edge or vertex, and its repair).
    if (!level.manifold())
      throw Error(fmt::format("scheme {} has no limit mask at the non-manifold places of this mesh, where no limit "
                              "point is defined: {}{}",
                              subdiv::quoted(tail.name), non_manifold_place(level),
                              prefix.empty() ? "" : " (on the level after the sequence's first schemes)"));
    throw Error(fmt::format(
        "scheme {} has no limit mask for this mesh; every candidate was refused:{}\n  {}`subdiv analyze {}` "
        "shows the eigenvalues behind this.", subdiv::quoted(tail.name), list,
        providers.empty() ? "" : fmt::format("Registered providers ({}) had no mask either. ", fmt::join(providers, ", ")),
        analyze_argument(tail)));
  }
  const std::string checked = check.first_children.empty()
                                  ? "checked: every V-face keeps its centroid one step down"
                                  : fmt::format("checked: l S = l for two steps of {}", tail.name);
  if (prefix.empty()) return {tail_mask, fmt::format("{} ({} on this mesh)", tail_mask->name(), checked)};

  auto composite = std::make_shared<CompositeLimit>(prefix, tail_mask, o);
  return {composite, fmt::format("{} (tail {} on the level after the prefix)", composite->name(), checked)};
}

}  // namespace subdiv
