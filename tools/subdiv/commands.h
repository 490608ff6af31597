#pragma once
// Subcommands of the `subdiv` tool. Each adds itself to the app and runs when chosen.
#include <CLI/CLI.hpp>

namespace subdiv::cli {

void add_refine_command(CLI::App& app);
void add_schemes_command(CLI::App& app);
void add_validate_command(CLI::App& app);
void add_analyze_command(CLI::App& app);

}  // namespace subdiv::cli
