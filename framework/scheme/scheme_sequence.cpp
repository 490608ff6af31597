#include "framework/scheme/scheme_sequence.h"

#include <fmt/format.h>
#include <set>

#include "framework/scheme/scheme.h"
#include "framework/util/error.h"
#include "framework/util/option_spelling.h"
#include "framework/util/short_text.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

// As many levels as `subdiv refine --levels` allows; more could not fit in memory anyway,
// and a sum of unbounded counts would overflow.
constexpr int kMaxLevelsPerPart = 30;

struct Part {
  std::string name;
  int levels = -1;  // -1: the remainder
};

std::vector<Part> split_spec(const std::string& spec) {
  std::vector<Part> parts;
  size_t start = 0;
  while (start <= spec.size()) {
    size_t end = spec.find(',', start);
    if (end == std::string::npos) end = spec.size();
    const std::string item = spec.substr(start, end - start);
    const size_t colon = item.rfind(':');
    Part part{item};
    if (colon != std::string::npos) {
      part.name = item.substr(0, colon);
      try {
        size_t used = 0;
        part.levels = std::stoi(item.substr(colon + 1), &used);
        if (used != item.size() - colon - 1 || part.levels < 0 || part.levels > kMaxLevelsPerPart)
          throw std::invalid_argument("");
      } catch (...) {
        throw OptionError(fmt::format("{{scheme}} {}: {} should be NAME:LEVELS with LEVELS a whole number from 0 to {}",
                                subdiv::quoted(shortened(spec)), subdiv::quoted(shortened(item)), kMaxLevelsPerPart));
      }
    }
    if (part.name.empty()) throw OptionError(fmt::format("{{scheme}} {}: empty scheme name", subdiv::quoted(spec)));
    parts.push_back(part);
    start = end + 1;
  }
  return parts;
}

std::set<std::string> parameter_names(const Scheme& s) {
  std::set<std::string> names;
  for (const auto& p : s.parameters) names.insert(p.name);
  if (s.curve)
    for (const auto& [name, value] : s.curve->parameters) names.insert(name);
  return names;
}

// A part of a sequence; its errors name the part within the sequence.
std::shared_ptr<const Scheme> part_scheme(const std::string& spec, size_t parts, const std::string& name,
                                          const ParameterOverrides& overrides) {
  if (parts == 1) return load_scheme(name, overrides);
  try {
    return load_scheme(name, overrides);
  } catch (const OptionError&) {
    throw;
  } catch (const Error& e) {
    throw Error(fmt::format("scheme sequence {}, part {}: {}", subdiv::quoted(shortened(spec)), subdiv::quoted(shortened(name)), e.what()));
  }
}

}  // namespace

SchemeSequence load_scheme_sequence(const std::string& spec, int levels, const ParameterOverrides& overrides) {
  std::vector<Part> parts = split_spec(spec);
  int fixed = 0, open = 0;
  for (const Part& p : parts) p.levels >= 0 ? fixed += p.levels : ++open;
  if (open > 1) throw OptionError(fmt::format("{{scheme}} {}: at most one scheme may omit its level count", subdiv::quoted(spec)));
  if (open == 1 && levels < fixed)
    throw OptionError(fmt::format("{{scheme}} {} fixes {} levels, more than {{levels}} {}", subdiv::quoted(spec), fixed, levels));
  SchemeSequence seq;
  std::set<std::string> used;
  for (Part& p : parts) {
    if (p.levels < 0) p.levels = parts.size() == 1 ? levels : levels - fixed;
    ParameterOverrides mine;
    const auto names = parameter_names(*part_scheme(spec, parts.size(), p.name, {}));
    for (const auto& [name, value] : overrides)
      if (names.count(name)) mine[name] = value, used.insert(name);
    seq.schemes.push_back(part_scheme(spec, parts.size(), p.name, mine));
    seq.runs.push_back({seq.schemes.back().get(), p.levels});
    seq.total_levels += p.levels;
  }
  for (const auto& [name, value] : overrides)
    if (!used.count(name))
      throw OptionError(fmt::format("no scheme in {} has a parameter {} (from {{param}} {}={}); {{scheme_list}} "
                                    "lists each scheme's parameters",
                                    subdiv::quoted(spec), subdiv::quoted(name), name, value));
  return seq;
}

}  // namespace subdiv
