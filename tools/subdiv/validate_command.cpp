// `subdiv validate FILE.json...`: check scheme files before using them.
#include <filesystem>
#include <fmt/format.h>

#include "commands.h"
#include "framework/scheme/scheme_validator.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"
#include "safe_print.h"

namespace subdiv::cli {

void add_validate_command(CLI::App& app) {
  auto files = std::make_shared<std::vector<std::string>>();
  auto range = std::make_shared<std::pair<int, int>>(3, 16);
  auto* cmd = app.add_subcommand("validate",
                                 "Check scheme files: structure, formulas, affine weights and symmetry for every valence");
  cmd->add_option("files", *files, "Scheme files (.json), built-in scheme names or plugins' scheme names")->required();
  const auto valences = CLI::Range(kMinCheckedValence, kMaxCheckedValence);
  cmd->add_option("--min-valence", range->first, "Smallest valence to check")->check(valences)->capture_default_str();
  cmd->add_option("--max-valence", range->second, "Largest valence to check")->check(valences)->capture_default_str();
  cmd->callback([files, range] {
    if (range->first > range->second)  // would check nothing and say "ok"
      throw Error(fmt::format("--min-valence {} is larger than --max-valence {}; give a range with min <= max",
                              range->first, range->second));
    int failed = 0;
    for (const auto& file : *files) {
      if (std::filesystem::path(file).filename() == "scheme.schema.json") {
        print_safe("{}: skipped (the JSON Schema, not a scheme)\n", file);
        continue;
      }
      const ValidationReport r = validate_scheme_file(file, range->first, range->second);
      if (r.ok() && !r.skipped.empty() && r.checks == 0) {
        print_safe("{}: skipped ({} scheme {}: {})\n", file, r.kind, subdiv::quoted(r.scheme_name), r.skipped);
        continue;
      }
      if (r.ok()) {
        print_safe("{}: ok ({} scheme {}, {} checks{}{})\n", file, r.kind, subdiv::quoted(r.scheme_name), r.checks,
                   r.skipped.empty() ? "" : "; not checked: ", r.skipped);
        for (const auto& note : r.notes) print_safe("  note: {}\n", note);
        continue;
      }
      ++failed;
      for (const auto& e : r.errors) print_safe(stderr, "{}\n", e.message);
    }
    if (failed) throw Error(fmt::format("{} of {} scheme file(s) failed validation", failed, files->size()));
  });
}

}  // namespace subdiv::cli
