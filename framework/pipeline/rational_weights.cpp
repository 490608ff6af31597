#include "framework/pipeline/rational_weights.h"

#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

std::optional<size_t> locate(const std::vector<DataArray>& point_data, const std::string& name,
                             const std::string& source) {
  if (!name.empty()) {
    for (size_t i = 0; i < point_data.size(); ++i)
      if (point_data[i].name == name) return i;
    std::vector<std::string> names;
    for (const DataArray& a : point_data) names.push_back(fmt::format("{}", subdiv::quoted(a.name)));
    throw Error(fmt::format("{}: no point array {} holds the rational weights; {}", source, subdiv::quoted(name),
                            names.empty() ? std::string("the mesh has no point arrays")
                                          : fmt::format("its point arrays are {}", fmt::join(names, ", "))));
  }
  for (size_t i = 0; i < point_data.size(); ++i)
    if (point_data[i].name == kWeightArrayName) return i;
  return std::nullopt;
}

void check_weights(const DataArray& a, const std::string& source) {
  if (a.components != 1)
    throw Error(fmt::format("{}: the rational weights {} have {} components; give one weight per vertex", source,
                            subdiv::quoted(a.name), a.components));
  for (size_t v = 0; v < a.values.size(); ++v)
    if (!(a.values[v] > 0) || !std::isfinite(a.values[v]))
      throw Error(fmt::format("{}: vertex {} (counted from 0) has the rational weight {} = {}; weights must be "
                              "positive and finite (a zero weight is a point at infinity, a negative one crosses it)",
                              source, v, a.name, a.values[v]));
}

}  // namespace

std::optional<size_t> find_rational_weights(std::vector<DataArray>& point_data, const std::string& name,
                                            const std::string& source) {
  const std::optional<size_t> at = locate(point_data, name, source);
  if (!at) return at;
  DataArray& a = point_data[*at];
  check_weights(a, source);
  a.integer = false;  // weights are averaged like the points, never taken by origin
  return at;
}

bool all_weights_one(std::span<const double> weights) {
  for (double w : weights)
    if (w != 1.0) return false;
  return true;
}

void to_homogeneous(std::span<double> xyz, std::span<const double> weights) {
  for (size_t v = 0; v < weights.size(); ++v)
    for (size_t c = 0; c < 3; ++c) xyz[3 * v + c] *= weights[v];
}

void from_homogeneous(std::span<double> xyz, std::span<const double> weights) {
  for (size_t v = 0; v < weights.size(); ++v)
    for (size_t c = 0; c < 3; ++c) xyz[3 * v + c] /= weights[v];
}

}  // namespace subdiv
