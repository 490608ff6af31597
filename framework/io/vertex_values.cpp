#include "framework/io/vertex_values.h"

#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <sstream>

#include "framework/util/error.h"
#include "framework/util/input_file.h"
#include "framework/util/quoted_text.h"

namespace subdiv {

std::vector<double> read_vertex_values(const std::string& file, const std::string& name, Index vertex_count) {
  const std::string text = read_input_file(file, "per-vertex values");
  std::vector<double> values;
  std::istringstream lines{std::string(without_utf8_bom(text))};
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
        throw Error(fmt::format("{} line {}: {} is not a finite number ({} of vertex {})", file, number,
                                subdiv::quoted(word.substr(0, 40)), name, values.size()));
      values.push_back(x);
    }
  }
  if (values.size() != size_t(vertex_count))
    throw Error(fmt::format("{}: {} values of {} for a mesh of {} vertices; give one per vertex, in vertex order",
                            file, values.size(), subdiv::quoted(name), vertex_count));
  return values;
}

std::map<std::string, std::vector<double>> read_vertex_parameter_files(const std::map<std::string, std::string>& files,
                                                                       Index vertex_count) {
  std::map<std::string, std::vector<double>> out;
  for (const auto& [name, file] : files) out[name] = read_vertex_values(file, name, vertex_count);
  return out;
}

}  // namespace subdiv
