#include "shared_options.h"

#include <fmt/format.h>

#include "framework/util/error.h"

namespace subdiv::cli {

CLI::Option* add_param_option(CLI::App* cmd, std::vector<std::string>& params) {
  return cmd->add_option("-p,--param", params, "Scheme parameter, name=value (repeatable), e.g. --param beta=warren");
}

ParameterOverrides parse_params(const std::vector<std::string>& params) {
  ParameterOverrides out;
  for (const auto& p : params) {
    const auto eq = p.find('=');
    if (eq == std::string::npos || eq == 0) throw Error(fmt::format("--param '{}' must be written name=value", p));
    out[p.substr(0, eq)] = p.substr(eq + 1);
  }
  return out;
}

CLI::Option* add_boundary_option(CLI::App* cmd, const std::string& flag, std::string& value) {
  return cmd
      ->add_option(flag, value,
                   "Boundary interpolation, as OpenSubdiv names it: edges-and-corners (boundary corners stay), "
                   "edges (corners follow the boundary curve), none")
      ->check(CLI::IsMember({"none", "edges", "edges-and-corners"}))
      ->capture_default_str();
}

BoundaryInterpolation boundary_from_name(const std::string& name) {
  if (name == "none") return BoundaryInterpolation::None;
  if (name == "edges") return BoundaryInterpolation::EdgesOnly;
  return BoundaryInterpolation::EdgesAndCorners;  // the option's check allows nothing else
}

CLI::Option* add_crease_method_option(CLI::App* cmd, std::string& value) {
  return cmd->add_option("--crease-method", value, "How semi-sharp crease sharpness decays: uniform or chaikin")
      ->check(CLI::IsMember({"uniform", "chaikin"}))
      ->capture_default_str();
}

CreaseMethod crease_method_from_name(const std::string& name) {
  return name == "chaikin" ? CreaseMethod::Chaikin : CreaseMethod::Uniform;
}

}  // namespace subdiv::cli
