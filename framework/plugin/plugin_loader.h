#pragma once
// Loading plugins: find them, check their record, let them register, and remember what
// happened to each. A faulty plugin (not a plugin, built for another interface, a name or
// scheme that is taken, a registration that throws) is refused with a reason that names
// its file, and loading carries on with the others: nothing of a refused plugin stays
// registered.
//
// Plugins are native code running in this process: only load plugins you trust.
#include <filesystem>
#include <string>
#include <vector>

namespace subdiv {

struct PluginStatus {
  std::string file;      // the library, as found
  // "--plugin" (a file named there), "--plugin folder" (a file in a folder named there),
  // "SUBDIV_PLUGIN_PATH" or "installed plugin folder"
  std::string found_by;
  bool loaded = false;
  std::string name, version;           // from the plugin's record, when it could be read
  std::string reason;                  // why it was refused (empty when loaded)
  std::vector<std::string> provides;   // what it registered, one line each
};

// Loads one library. Never throws for a faulty plugin; the status says why it was refused.
// Only regular files whose ELF headers, segments and sections are complete reach dlopen
// (elf_check.h): a half-copied library or a FIFO is refused, never loaded.
PluginStatus load_plugin(const std::filesystem::path& file, const std::string& found_by = "--plugin");

struct PluginSearch {
  std::vector<std::string> paths;  // --plugin: library files, or folders of them
  bool environment = true;         // also SUBDIV_PLUGIN_PATH (':'-separated files or folders)
  bool installed = true;           // also the installed plugin folders (installed_plugin_dirs)
};

// Loads, in this order, the given paths, SUBDIV_PLUGIN_PATH and the installed plugin
// folders. A folder contributes its shared libraries (*.so) in name order. Each file is
// tried once per process, however often it is found. A given path that does not exist is
// refused; folders on SUBDIV_PLUGIN_PATH or installed that do not exist are skipped.
// SUBDIV_NO_INSTALLED_PLUGINS=1 in the environment skips the installed folders (tests).
// Returns the statuses of the files tried by this call.
std::vector<PluginStatus> load_plugins(const PluginSearch& search);

// Every file tried in this process, in order.
std::vector<PluginStatus> plugin_statuses();

// The installed plugin folders: <folder of libsubdiv>/subdivkit/plugins (so an installed
// tree works wherever it is moved) and the folder configured at build time
// (CMAKE_INSTALL_FULL_LIBDIR/subdivkit/plugins), without repeats.
std::vector<std::filesystem::path> installed_plugin_dirs();

// The plugin interface version this SubdivKit speaks (plugin_api.h).
unsigned plugin_interface_version();

}  // namespace subdiv
