#pragma once
// Plugin rules as the engine calls them, guarded: a C++ rule's rows are checked before they
// reach the stencil tables (every parent vertex index within the parent level, every weight
// finite: an index past the end read outside the array, -5 read garbage and exited 0), and
// any exception a plugin throws, of any type, becomes a subdiv::Error naming the plugin and
// the scheme (a non-std::exception throw ended in std::terminate). Internal to plugin/.
#include <string>

#include "framework/scheme/curve_scheme.h"
#include "framework/rules/code_rules.h"

namespace subdiv {

// `who` names the plugin and the scheme in messages, e.g. "plugin 'sqrt2' (lib.so), scheme 'x'".
CodeRules checked_code_rules(CodeRules rules, std::string who);
NonlinearRule checked_nonlinear_rule(NonlinearRule rule, std::string who);
PolylineRule checked_polyline_rule(PolylineRule rule, std::string who);

// Calls `make` (a plugin's function that builds rules from parameters) and turns whatever
// it throws into subdiv::Error naming `who` and `what`.
template <typename Make>
auto call_plugin(const std::string& who, const char* what, Make&& make) -> decltype(make());
[[noreturn]] void rethrow_plugin_exception(const std::string& who, const char* what);

template <typename Make>
auto call_plugin(const std::string& who, const char* what, Make&& make) -> decltype(make()) {
  try {
    return make();
  } catch (...) {
    rethrow_plugin_exception(who, what);
  }
}

}  // namespace subdiv
