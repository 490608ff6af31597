#include "shared_options.h"

#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <sstream>

#include "framework/util/error.h"
#include "framework/util/input_file.h"

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

CLI::Option* add_vertex_param_option(CLI::App* cmd, std::vector<std::string>& specs) {
  return cmd->add_option("--vertex-param", specs,
                         "A scheme parameter given per vertex, name=FILE (repeatable): FILE holds one value per "
                         "vertex of the input mesh, in vertex order ('#' comments); only parameters the scheme "
                         "declares \"per_vertex\" (`subdiv schemes` marks them), e.g. lambda of catmull-clark-shape");
}

VertexParameters read_vertex_params(const std::vector<std::string>& specs, Index vertex_count) {
  VertexParameters out;
  for (const std::string& spec : specs) {
    const auto eq = spec.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
      throw Error(fmt::format("--vertex-param '{}' must be written name=FILE", spec));
    const std::string name = spec.substr(0, eq);
    if (out.count(name)) throw Error(fmt::format("--vertex-param: '{}' is given twice", name));
    out[name] = read_vertex_values(spec.substr(eq + 1), name, vertex_count);
  }
  return out;
}

std::vector<double> read_vertex_values(const std::string& file, const std::string& name, Index vertex_count) {
  const std::string text = read_input_file(file, "per-vertex values");
  std::vector<double> values;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    for (char& c : line)
      if (c == ',' || c == '\t' || c == '\r') c = ' ';
    std::istringstream words(line);
    std::string word;
    while (words >> word) {
      double x = 0;
      const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), x);
      if (ec != std::errc() || end != word.data() + word.size() || !std::isfinite(x))
        throw Error(fmt::format("{} line {}: '{}' is not a finite number ({} of vertex {})", file, number,
                                word.substr(0, 40), name, values.size()));
      values.push_back(x);
    }
  }
  if (values.size() != size_t(vertex_count))
    throw Error(fmt::format("{}: {} values of '{}' for a mesh of {} vertices; give one per vertex, in vertex order",
                            file, values.size(), name, vertex_count));
  return values;
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
