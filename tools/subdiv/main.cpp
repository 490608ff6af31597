// The `subdiv` command line: refine meshes with any scheme, list schemes.
#include <CLI/CLI.hpp>
#include <csignal>
#include <fmt/format.h>

#include "commands.h"
#include "shared_options.h"
#include "usage_errors.h"
#include "framework/io/vtk/vtk_formats.h"
#include "framework/util/error.h"
#include "framework/util/memory_limit.h"
#include "framework/util/quoted_text.h"

int main(int argc, char** argv) {
  // A file size limit (ulimit -f) then fails the write with EFBIG, which the writers report
  // ("larger than allowed") and clean up after, instead of killing the process with SIGXFSZ
  // and leaving the temporary file behind. Python ignores the signal the same way.
  std::signal(SIGXFSZ, SIG_IGN);
  subdiv::register_vtk_formats();  // before the help texts list the formats
  CLI::App app{"subdiv - define, run and analyse subdivision schemes (SubdivKit " SUBDIV_CLI_VERSION ")"};
  app.set_version_flag("--version", "SubdivKit " SUBDIV_CLI_VERSION);
  app.require_subcommand(1);
  app.footer("Run `subdiv COMMAND --help` for each command's options.\n"
             "Schemes are JSON files (docs/scheme-format.md) or plugins (docs/plugins.md).\n" +
             subdiv::cli::exit_code_help());
  subdiv::cli::add_refine_command(app);
  subdiv::cli::add_schemes_command(app);
  subdiv::cli::add_validate_command(app);
  subdiv::cli::add_plugins_command(app);
  subdiv::cli::add_interpolate_command(app);
  subdiv::cli::add_analyze_command(app);
  subdiv::cli::add_evaluate_command(app);
  subdiv::cli::add_parameterize_command(app);
  subdiv::cli::add_plugin_options(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return subdiv::cli::report_parse_error(app, e, argc, argv);
  } catch (const subdiv::OptionError& e) {  // the pipeline's words, spelled as our options
    fmt::print(stderr, "subdiv: error: {}\n", subdiv::terminal_safe(e.spelled(subdiv::cli::cli_option_spelling())));
    return subdiv::cli::kExitRefused;
  } catch (const subdiv::Error& e) {
    fmt::print(stderr, "subdiv: error: {}\n", subdiv::terminal_safe(e.what()));
    return subdiv::cli::kExitRefused;
  } catch (const std::bad_alloc&) {  // the memory guard's words, never "internal error"
    fmt::print(stderr, "subdiv: error: {}\n", subdiv::out_of_memory_message("running the command"));
    return subdiv::cli::kExitRefused;
  } catch (const std::exception& e) {
    fmt::print(stderr, "subdiv: internal error: {}\n", subdiv::terminal_safe(e.what()));
    return subdiv::cli::kExitInternal;
  }
  return 0;
}
