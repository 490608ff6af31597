#include "framework/rules/definition_order.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <string>
#include <string_view>
#include <unordered_map>

#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

bool starts_name(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool in_name(char c) { return starts_name(c) || (c >= '0' && c <= '9'); }

// The definitions each definition's expression names, by index (repeats allowed).
std::vector<std::vector<size_t>> references(const std::vector<NamedFormula>& defs) {
  std::unordered_map<std::string_view, size_t> index;
  for (size_t i = 0; i < defs.size(); ++i) index.emplace(defs[i].name, i);
  std::vector<std::vector<size_t>> out(defs.size());
  for (size_t i = 0; i < defs.size(); ++i) {
    const std::string& e = defs[i].expression;
    for (size_t p = 0; p < e.size();) {
      if (!starts_name(e[p]) || (p > 0 && (in_name(e[p - 1]) || e[p - 1] == '.'))) {
        ++p;
        continue;
      }
      size_t end = p;
      while (end < e.size() && in_name(e[end])) ++end;
      if (auto it = index.find(std::string_view(e).substr(p, end - p)); it != index.end())
        out[i].push_back(it->second);
      p = end;
    }
  }
  return out;
}

// A cycle in the reference graph as a list of indices (first == last), or empty.
// Iterative depth-first search: a fuzzed file may chain thousands of definitions.
std::vector<size_t> find_cycle(const std::vector<std::vector<size_t>>& refs) {
  enum : char { kNew, kOpen, kDone };
  std::vector<char> state(refs.size(), kNew);
  for (size_t root = 0; root < refs.size(); ++root) {
    if (state[root] != kNew) continue;
    std::vector<std::pair<size_t, size_t>> stack{{root, 0}};  // node, next edge
    state[root] = kOpen;
    while (!stack.empty()) {
      auto& [node, edge] = stack.back();
      if (edge == refs[node].size()) {
        state[node] = kDone;
        stack.pop_back();
        continue;
      }
      const size_t next = refs[node][edge++];
      if (state[next] == kOpen) {  // back to a definition on the current path: a cycle
        std::vector<size_t> cycle;
        size_t k = 0;
        while (stack[k].first != next) ++k;
        for (; k < stack.size(); ++k) cycle.push_back(stack[k].first);
        cycle.push_back(next);
        return cycle;
      }
      if (state[next] == kNew) {
        state[next] = kOpen;
        stack.push_back({next, 0});
      }
    }
  }
  return {};
}

}  // namespace

void check_definition_order(const std::vector<NamedFormula>& defs) {
  const auto refs = references(defs);
  if (const auto cycle = find_cycle(refs); !cycle.empty()) {
    const NamedFormula& first = defs[cycle.front()];
    std::vector<std::string_view> names;
    for (size_t i : cycle) names.push_back(defs[i].name);
    if (cycle.size() == 2)
      throw Error(fmt::format("{}: definition {} refers to itself (a cycle: {}); a definition may use only "
                              "parameters, n, k, j, l and the definitions before it",
                              first.where, subdiv::quoted(first.name), fmt::join(names, " -> ")));
    throw Error(fmt::format("{}: definitions refer to each other in a cycle: {}; a definition may use only "
                            "parameters, n, k, j, l and the definitions before it, so break the cycle",
                            first.where, fmt::join(names, " -> ")));
  }
  for (size_t i = 0; i < defs.size(); ++i)
    for (size_t j : refs[i])
      if (j > i)
        throw Error(fmt::format("{}: definition {} uses {}, which is defined after it; move {} before {}",
                                defs[i].where, subdiv::quoted(defs[i].name), subdiv::quoted(defs[j].name), subdiv::quoted(defs[j].name), subdiv::quoted(defs[i].name)));
}

}  // namespace subdiv
