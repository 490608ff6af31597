#include "shared_options.h"

#include <fmt/format.h>

#include "framework/pipeline/parameter_text.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv::cli {

const OptionSpelling& cli_option_spelling() {
  static const OptionSpelling spelling = {
      {"scheme", "--scheme"},           {"levels", "--levels"},
      {"start_level", "--start-level"}, {"boundary", "--boundary"},
      {"crease_method", "--crease-method"}, {"fvar_boundary", "--fvar-boundary"},
      {"smooth_triangles", "--smooth-triangles"}, {"feature_angle", "--feature-angle"},
      {"features", "--features"},       {"vertex_param", "--vertex-param"},
      {"limit", "--limit"},             {"normals", "--normals"},
      {"arrays", "--arrays"},           {"threads", "--threads"},
      {"param", "--param"},             {"scheme_list", "`subdiv schemes`"},
      {"min_valence", "--min-valence"}, {"max_valence", "--max-valence"},
      {"select", "--select"},           {"max_iterations", "--max-iter"},
      {"valences", "--valence"},        {"boundary_analysis", "--boundary"},
      {"samples", "--samples"},         {"tolerance", "--tolerance"},
      {"transitions", "--transitions"},
      {"derivatives", "--derivatives"}, {"approximate_bezier", "--approximate bezier"},
      {"approximate_gregory", "--approximate gregory"}};
  return spelling;
}

CLI::Option* add_param_option(CLI::App* cmd, std::vector<std::string>& params) {
  return cmd->add_option("-p,--param", params, "Scheme parameter, name=value (repeatable), e.g. --param beta=warren");
}

ParameterOverrides parse_params(const std::vector<std::string>& params) {
  return parse_parameter_assignments(params, "--param");
}

CLI::Option* add_vertex_param_option(CLI::App* cmd, std::vector<std::string>& specs) {
  return cmd->add_option("--vertex-param", specs,
                         "A scheme parameter given per vertex, name=FILE (repeatable): FILE holds one value per "
                         "vertex of the input mesh, in vertex order ('#' comments); only parameters the scheme "
                         "declares \"per_vertex\" (`subdiv schemes` marks them), e.g. lambda of catmull-clark-shape");
}

std::map<std::string, std::string> vertex_param_files(const std::vector<std::string>& specs) {
  std::map<std::string, std::string> out;
  for (const std::string& spec : specs) {
    const auto eq = spec.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
      throw Error(fmt::format("--vertex-param {} must be written name=FILE", subdiv::quoted(spec)));
    const std::string name = spec.substr(0, eq);
    if (out.count(name)) throw Error(fmt::format("--vertex-param: {} is given twice", subdiv::quoted(name)));
    out[name] = spec.substr(eq + 1);
  }
  return out;
}

CLI::Option* add_boundary_option(CLI::App* cmd, const std::string& flag, std::string& value) {
  return cmd->add_option(flag, value, "Boundary interpolation, as OpenSubdiv names it: " + choices_help(boundary_choices()))
      ->check(CLI::IsMember(choice_names(boundary_choices())))
      ->capture_default_str();
}

CLI::Option* add_crease_method_option(CLI::App* cmd, std::string& value) {
  return cmd->add_option("--crease-method", value,
                         "How semi-sharp crease sharpness decays: " + choices_help(crease_method_choices()))
      ->check(CLI::IsMember(choice_names(crease_method_choices())))
      ->capture_default_str();
}

CLI::Option* add_fvar_boundary_option(CLI::App* cmd, std::string& value, const std::string& what) {
  return cmd->add_option("--fvar-boundary", value,
                         what + ", as OpenSubdiv's linear-interpolation modes: " + choices_help(face_varying_choices()) +
                             "; a mesh's 't facevaryinginterpolateboundary' tag does the same unless this option is given")
      ->check(CLI::IsMember(choice_names(face_varying_choices())))
      ->capture_default_str();
}

}  // namespace subdiv::cli
