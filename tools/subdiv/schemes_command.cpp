// `subdiv schemes`: the built-in and user schemes with their descriptions and parameters.
#include <fmt/format.h>

#include "commands.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "safe_print.h"

namespace subdiv::cli {
namespace {

void print_parameters(const std::string& name, const std::string& kind) {
  try {
    const auto specs = kind == "curve" ? load_curve(name)->parameter_specs : load_scheme(name)->parameters;
    for (const auto& p : specs) {
      if (p.is_choice) {
        std::string list;
        for (auto& c : p.choices) list += (list.empty() ? "" : "|") + c;
        print_safe("      --param {}={}  (default {}) {}\n", p.name, list, p.choice, p.description);
      } else {
        print_safe("      --param {}=<number>  (default {}) {}{}\n", p.name, p.value, p.description,
                   p.per_vertex ? fmt::format(" [per vertex: --vertex-param {}=FILE]", p.name) : "");
      }
    }
  } catch (const Error& e) {
    print_safe("      (cannot load: {})\n", e.what());
  }
}

void run(bool verbose) {
  for (const char* kind : {"surface", "curve"}) {
    print_safe("{} schemes:\n", kind);
    for (const auto& s : list_schemes()) {
      if (s.kind != kind) continue;
      print_safe("  {:<22} {:<28} {}\n", s.name, "[" + s.origin + "]", s.description);
      if (verbose) print_safe("      file: {}\n", s.path);
      print_parameters(s.name, s.kind);
    }
  }
}

}  // namespace

void add_schemes_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("schemes", "List the schemes and where each comes from: built-in, SUBDIV_SCHEME_PATH, "
                                            "or the plugin that registered it");
  auto verbose = std::make_shared<bool>(false);
  cmd->add_flag("-v,--verbose", *verbose, "Also show where each scheme file is");
  cmd->callback([verbose] { run(*verbose); });
}

}  // namespace subdiv::cli
