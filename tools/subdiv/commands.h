#pragma once
// Subcommands of the `subdiv` tool. Each adds itself to the app and runs when chosen.
#include <CLI/CLI.hpp>

namespace subdiv::cli {

void add_refine_command(CLI::App& app);
void add_schemes_command(CLI::App& app);
void add_validate_command(CLI::App& app);
void add_analyze_command(CLI::App& app);
void add_interpolate_command(CLI::App& app);
void add_plugins_command(CLI::App& app);
void add_evaluate_command(CLI::App& app);
void add_parameterize_command(CLI::App& app);
// --plugin on the app and every subcommand (call after adding them); loads the plugins
// before the chosen subcommand runs.
void add_plugin_options(CLI::App& app);

}  // namespace subdiv::cli
