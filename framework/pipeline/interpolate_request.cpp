#include "framework/pipeline/interpolate_request.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <sstream>

#include "framework/interpolation/curve_limits.h"
#include "framework/io/mesh_level.h"
#include "framework/pipeline/scheme_source.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "framework/util/option_spelling.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

void say(const InterpolateRequest& r, const std::string& phase) {
  if (r.progress) r.progress(phase);
}

// ---- the scheme: one curve scheme, or a surface scheme or sequence --------------------------

bool is_curve(const SchemeSource& s) {
  try {
    if (s.is_json_text) return scheme_text_kind(s.text, s.label) == "curve";
    return s.text.find_first_of(",:") == std::string::npos && scheme_kind(s.text) == "curve";
  } catch (const Error&) {
    return false;  // unknown names: the surface loader lists the known ones
  }
}

std::shared_ptr<const CurveScheme> load_curve_source(const SchemeSource& s) {
  if (s.is_json_text) return load_curve_text(s.text, s.label, s.parameters);
  return load_curve(s.text, s.parameters);
}

// Sequences are for surfaces; a curve scheme inside one gets a clear refusal instead of the
// surface loader's.
void refuse_curve_schemes(const std::string& sequence) {
  std::string name;
  std::istringstream runs(sequence);
  while (std::getline(runs, name, ',')) {
    name = name.substr(0, name.find(':'));
    bool curve = false;
    try {
      curve = scheme_kind(name) == "curve";
    } catch (const Error&) {
      // Unknown names are reported by the loader, with the known ones.
    }
    if (curve)
      throw OptionError(fmt::format("{{scheme}}: {} is a curve scheme inside a sequence; polylines are interpolated "
                                    "with one curve scheme ({{scheme}} {})",
                                    subdiv::quoted(name), name));
  }
}

SchemeSequence load_surface_source(const InterpolateRequest& r) {
  if (!r.scheme.is_json_text) refuse_curve_schemes(r.scheme.text);
  return load_surface_sequence(r.scheme, r.levels, r.scheme.parameters);
}

// ---- the limit operator --------------------------------------------------------------------

// Inside the longest polyline, a point's row shows the scheme's interior limit weights.
std::string describe_curve_limit(const StencilTable& limit, const CurveLevel& level) {
  Index longest = 0;
  for (Index p = 1; p < level.polyline_count(); ++p)
    if (level.size(p) > level.size(longest)) longest = p;
  const Index v = level.polyline(longest)[size_t(level.size(longest) / 2)];
  std::vector<std::string> terms;
  for (Index i = limit.offsets[v]; i < limit.offsets[v + 1]; ++i) terms.push_back(fmt::format("{:.6g}", limit.weights[i]));
  return fmt::format("the limit curve at each point's parameter; inside a polyline the weights ({})",
                     fmt::join(terms, ", "));
}

void check_surface_mesh(const InterpolateRequest& r) {
  if (r.mesh.face_count() > 0) return;
  const Index lines = r.mesh.line_count();
  throw OptionError(fmt::format("{}: the mesh has no faces{}; surface schemes interpolate surface meshes{}", r.mesh_name,
                                lines > 0 ? fmt::format(" (it has {} polyline{})", lines, lines == 1 ? "" : "s") : "",
                                lines > 0 ? ", polylines take a curve scheme (e.g. {scheme} cubic-bspline)" : ""));
}

LimitSelectionOptions selection_options(const InterpolateRequest& r) {
  LimitSelectionOptions o;
  o.features.boundary = r.boundary;
  o.first_step = r.start_level;
  o.vertex_parameters = r.vertex_parameters;
  return o;
}

// The checked limit masks of the sequence at `base`; a one-off first step on its own (Lin
// et al. 2015's shape step) has no limit, and the message says how to run it.
// Its other refusals name the mesh, which the masks were refused on.
LimitChoice surface_limit(const SchemeSequence& seq, const Level& base, const LimitSelectionOptions& options,
                          const std::string& mesh_name) {
  try {
    return select_limit(seq, base, options);
  } catch (const Error& e) {
    if (seq.runs.size() == 1 && declares_parameter(seq, "lambda"))
      throw OptionError(fmt::format("{}\n  {} has a shape parameter lambda: if it is a first step (Lin et al. 2015), "
                                    "make it the first run of a sequence, {{scheme}} {}:1,S, with S the scheme that "
                                    "repeats",
                                    e.what(), subdiv::quoted(seq.schemes[0]->name), seq.schemes[0]->name));
    if (dynamic_cast<const OptionError*>(&e)) throw;  // about the request's options, not the mesh
    throw Error(fmt::format("{}: {}", mesh_name, e.what()));
  }
}

// ---- the iteration -------------------------------------------------------------------------

// Theorem 2 (Lin et al. 2015) for any limit operator: where the fixed vertices' limit points end.
std::string theorem_two_note(const StencilTable& limit, const std::vector<double>& targets,
                             const std::vector<std::uint8_t>& moving, const ProgressiveResult& r) {
  double offset = 0, gap = 0;
  try {
    const std::vector<double> predicted = predicted_fixed_offsets(limit, targets, moving);
    for (size_t v = 0; v < moving.size(); ++v) {
      if (moving[v]) continue;
      double d2 = 0, e2 = 0;
      for (int c = 0; c < 3; ++c) {
        const double d = targets[3 * v + c] - r.limit[3 * v + c];
        d2 += d * d, e2 += (d - predicted[3 * v + c]) * (d - predicted[3 * v + c]);
      }
      offset = std::max(offset, std::sqrt(d2)), gap = std::max(gap, std::sqrt(e2));
    }
  } catch (const Error& e) {
    return fmt::format("fixed vertices: stay in place; theorem 2 not evaluated: {}", e.what());
  }
  return fmt::format("fixed vertices: stay in place; their limit points end up to {:.6g} from them "
                     "(theorem 2, D_Q = D_Q^0 - E M^-1 D_P^0, agrees to {:.1e})",
                     offset, gap);
}

void run_iteration(const InterpolateRequest& r, const StencilTable& limit, InterpolateResult& out) {
  std::vector<std::uint8_t> moving = r.moving;
  if (moving.empty()) moving.assign(size_t(r.mesh.vertex_count()), 1);
  if (moving.size() != size_t(r.mesh.vertex_count()))
    throw OptionError(fmt::format("{{select}}: {} flags for {} vertices", moving.size(), r.mesh.vertex_count()));
  if (r.max_iterations < 0) throw OptionError("{max_iterations} must be 0 or more");
  ProgressiveOptions po;
  po.tolerance = r.tolerance >= 0 ? r.tolerance : default_interpolation_tolerance(r.mesh.positions);
  po.max_iterations = r.max_iterations;
  if (r.iteration) po.observer = [&](const IterationState& s) { r.iteration(s.record); };
  out.tolerance = po.tolerance;
  out.vertices = Index(moving.size());
  out.moving = Index(std::count(moving.begin(), moving.end(), std::uint8_t(1)));
  out.iteration = progressive_interpolation(limit, r.mesh.positions, moving, po);
  if (out.moving < out.vertices) out.fixed_note = theorem_two_note(limit, r.mesh.positions, moving, out.iteration);
}

// The limit operator, and in `out` what a front-end needs to refine the result.
LimitOperator prepare_limit(const InterpolateRequest& r, InterpolateResult& out) {
  if (is_curve(r.scheme)) {
    out.curve = load_curve_source(r.scheme);
    out.curve_base = curve_level_from_mesh(r.mesh, r.mesh_name);
    say(r, "finding the limit points");
    StencilTable table = curve_limit_stencils(*out.curve, out.curve_base);
    std::string description = describe_curve_limit(table, out.curve_base);
    return {std::move(table), std::move(description)};
  }
  out.sequence = load_surface_source(r);
  check_surface_mesh(r);
  out.base = level_from_mesh(r.mesh, r.mesh_name);
  out.options = selection_options(r);
  say(r, "finding the limit masks");
  const LimitChoice choice = surface_limit(out.sequence, out.base, out.options, r.mesh_name);
  return {choice.evaluator->limit_stencils(out.base, r.start_level), choice.description};
}

}  // namespace

LimitOperator limit_operator(const InterpolateRequest& request) {
  InterpolateResult unused;
  return prepare_limit(request, unused);
}

InterpolateResult interpolate_mesh(InterpolateRequest request) {
  InterpolateResult out;
  const LimitOperator limit = prepare_limit(request, out);
  out.limit_description = limit.description;
  run_iteration(request, limit.table, out);
  return out;
}

}  // namespace subdiv
