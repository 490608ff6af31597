// Plugins on the command line: `--plugin PATH` (repeatable) on every subcommand, plugins
// loaded before any subcommand runs, and `subdiv plugins` listing what was found.
#include <cstdlib>
#include <fmt/format.h>
#include <memory>

#include "commands.h"
#include "framework/plugin/plugin_loader.h"
#include "framework/util/error.h"
#include "safe_print.h"

namespace subdiv::cli {
namespace {

constexpr const char* kPluginHelp =
    "Load a SubdivKit plugin (a shared library; repeatable). Plugins are native code: load only "
    "plugins you trust. Also loaded: SUBDIV_PLUGIN_PATH (':'-separated files or folders) and the "
    "installed plugin folder";

void print_status(const PluginStatus& s) {
  if (s.loaded) {
    print_safe("loaded   {} {}  {} ({})\n", s.name, s.version, s.file, s.found_by);
    for (const auto& line : s.provides) print_safe("           {}\n", line);
  } else {
    const std::string who = s.name.empty() ? "" : fmt::format("{} {}  ", s.name, s.version);
    print_safe("refused  {}{} ({})\n           reason: {}\n", who, s.file, s.found_by, s.reason);
  }
}

// A plugin the user named with --plugin and that was refused: the run cannot be what they
// asked for. Plugins found by search (SUBDIV_PLUGIN_PATH, installed) only warn.
bool explicitly_requested(const PluginStatus& s) { return s.found_by == "--plugin"; }

void refuse_requested_plugins(const std::vector<PluginStatus>& statuses) {
  std::string refused;
  for (const auto& s : statuses)
    if (!s.loaded && explicitly_requested(s)) refused += fmt::format("\n  {}: {}", s.file, s.reason);
  if (!refused.empty())
    throw Error(fmt::format("a plugin given with --plugin was refused:{}\nfix or rebuild it, or leave out its "
                            "--plugin option",
                            refused));
}

void run_plugins_command(bool verbose) {
  const auto statuses = plugin_statuses();
  if (verbose) {
    print_safe("plugin interface {}\n", plugin_interface_version());
    const char* env = std::getenv("SUBDIV_PLUGIN_PATH");
    print_safe("SUBDIV_PLUGIN_PATH: {}\n", env ? env : "(not set)");
    for (const auto& dir : installed_plugin_dirs()) print_safe("installed plugin folder: {}\n", dir.string());
  }
  if (statuses.empty()) {
    print_safe("no plugins found; give --plugin PATH, set SUBDIV_PLUGIN_PATH, or install plugins into {}\n",
               installed_plugin_dirs().back().string());
    return;
  }
  for (const auto& s : statuses) print_status(s);
  refuse_requested_plugins(statuses);
}

}  // namespace

void add_plugin_options(CLI::App& app) {
  auto paths = std::make_shared<std::vector<std::string>>();
  auto add_option = [paths](CLI::App* cmd) {
    cmd->add_option_function<std::vector<std::string>>(
           "--plugin", [paths](const std::vector<std::string>& given) { paths->insert(paths->end(), given.begin(), given.end()); },
           kPluginHelp)
        ->type_name("PATH")
        ->allow_extra_args(false);
  };
  add_option(&app);
  for (CLI::App* cmd : app.get_subcommands([](CLI::App*) { return true; })) add_option(cmd);
  // Runs after every option is parsed and before the chosen subcommand's callback.
  app.parse_complete_callback([&app, paths] {
    const auto statuses = load_plugins({*paths});
    if (app.got_subcommand("plugins")) return;  // it lists them itself, then refuses
    refuse_requested_plugins(statuses);
    for (const auto& s : statuses)
      if (!s.loaded)
        print_safe(stderr, "subdiv: warning: plugin {} refused: {}\n", s.file, s.reason);
  });
}

void add_plugins_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("plugins", "List the plugins found (--plugin, SUBDIV_PLUGIN_PATH, installed folder): "
                                            "loaded, or refused with the reason");
  auto verbose = std::make_shared<bool>(false);
  cmd->add_flag("-v,--verbose", *verbose, "Also show the interface version and the folders searched");
  cmd->footer("Plugins are native code running inside subdiv: load only plugins you trust. See docs/plugins.md.");
  cmd->callback([verbose] { run_plugins_command(*verbose); });
}

}  // namespace subdiv::cli
