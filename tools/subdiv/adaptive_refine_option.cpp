#include "adaptive_refine_option.h"

#include <cmath>
#include <fmt/format.h>

#include "framework/io/formats.h"
#include "framework/io/mesh_write.h"
#include "framework/pipeline/adaptive_request.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"
#include "shared_options.h"
#include "safe_print.h"

namespace subdiv::cli {

void add_adaptive_options(CLI::App* cmd, AdaptiveArgs& a) {
  cmd->add_option("--adaptive", a.levels,
                  "Feature-adaptive refinement up to level L (--adaptive L, or --adaptive -l L): only faces "
                  "touching an extraordinary vertex, a crease, a sharp vertex or a hole (and with --tolerance faces "
                  "not within it) are split; watertight output (coarse faces take the finer vertices along their "
                  "edges), cell arrays face_level and base_face; with --limit every vertex on the limit surface "
                  "(docs/limit.md)")
      ->expected(0, 1)
      ->check(CLI::Range(0, kMaxAdaptiveLevel));
  add_tolerance_option(cmd, a.tolerance);
  add_transitions_option(cmd, a.transitions);
}

void resolve_adaptive_level(const CLI::App& cmd, AdaptiveArgs& a, int levels, bool levels_given) {
  const CLI::Option* option = cmd.get_option("--adaptive");
  if (option->count() == 0) return;
  // CLI11 records a bare `--adaptive` (no value, or an option next) as one empty result.
  const bool bare = option->results().empty() || option->results().front().empty();
  if (!bare) {
    if (levels_given && levels != a.levels)
      throw Error(fmt::format("--adaptive {} and -l {} ask for two finest levels: give the level once "
                              "(--adaptive {} or --adaptive -l {})",
                              a.levels, levels, a.levels, a.levels));
    return;
  }
  if (levels > kMaxAdaptiveLevel)
    throw Error(fmt::format("--adaptive -l {}: adaptive refinement goes to level {} at most", levels,
                            kMaxAdaptiveLevel));
  a.levels = levels;
}

void add_tolerance_option(CLI::App* cmd, double& tolerance) {
  cmd->add_option("--tolerance", tolerance,
                  "With --adaptive: also split every face whose bilinear patch through its corners' limit points is "
                  "farther than T from the limit surface (measured at 5 x 5 points per face), up to level L");
}

void add_transitions_option(CLI::App* cmd, std::string& transitions) {
  cmd->add_option("--transitions", transitions,
                  "With --adaptive: how a coarse face next to finer ones is written: polygons (the default: one "
                  "polygon with the finer vertices along its edges as corners) or triangles (that polygon as "
                  "triangles and quads of the same vertices, as OpenSubdiv's transition patterns)")
      ->check(CLI::IsMember({"polygons", "triangles"}));
}

void run_adaptive_refine(RefineRequest request, const AdaptiveArgs& a, bool limit, bool in_pieces,
                         const std::string& output, bool quiet, Progress& progress,
                         std::chrono::steady_clock::time_point t0) {
  if (!(a.tolerance >= 0) || !std::isfinite(a.tolerance))
    throw Error(fmt::format("--tolerance {}: give a distance >= 0 (0: split only around features)", a.tolerance));
  if (in_pieces) throw Error("--adaptive refines whole meshes: leave out --pieces and --max-memory");
  const std::string ext = lowercase_extension(output);
  if (ext == ".pvd" || ext == ".pvtp")
    throw Error(fmt::format("-o {}: --adaptive writes one mesh (.vtp, .obj, .ply, .off, .stl)", subdiv::quoted(output)));
  AdaptiveRequest r;
  r.refine = std::move(request);
  r.refine.levels = a.levels;
  r.tolerance = a.tolerance;
  r.limit = limit;
  r.transitions = transitions_from_name(a.transitions);
  AdaptiveResult result = refine_adaptive_request(std::move(r));
  for (const std::string& w : result.warnings) print_safe(stderr, "subdiv: warning: {}\n", w);
  const std::string summary = adaptive_summary(result);
  progress.say(fmt::format("writing {}", output));
  write_mesh(output, adaptive_mesh_data(std::move(result.mesh), std::move(result.point_arrays), std::move(result.face_varying)),
             [&progress](double done) { progress.fraction(done); });
  progress.done();
  if (quiet) return;
  for (const auto& note : result.notes) print_safe("{}\n", spell_options(note, cli_option_spelling()));
  print_safe("adaptive refinement of {} to level {}: {} in {:.3f} s -> {}\n", result.scheme_label, a.levels,
             summary,
             seconds_since(t0), output);
}

}  // namespace subdiv::cli
