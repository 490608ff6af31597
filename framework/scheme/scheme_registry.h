#pragma once
// Finding and loading schemes by name or path.
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace subdiv {

struct Scheme;
struct CurveScheme;
using ParameterOverrides = std::map<std::string, std::string>;

// `name_or_path` is a built-in scheme name (a file in the scheme directory) or a path
// to a .json file. Parameter overrides come from --param name=value.
std::shared_ptr<const Scheme> load_scheme(const std::string& name_or_path,
                                          const ParameterOverrides& overrides = {});

// The file a built-in name or a path stands for; throws with the known names if none.
std::string scheme_file_path(const std::string& name_or_path);

// How a message tells the user to name `scheme` with `-s`: its name where the name finds
// it (built-in, search path, plugin), else its file.
std::string scheme_argument(const Scheme& scheme);

// The options a command line needs before `scheme_argument(scheme)` finds the scheme again:
// " --plugin FILE" for each plugin that registered the scheme or its splits ("" for a
// scheme of built-in parts). A plugin loaded from SUBDIV_PLUGIN_PATH or the installed folder
// would be found without it; naming it again is harmless (each file is loaded once).
std::string scheme_plugin_options(const Scheme& scheme);

// A curve scheme by built-in name, plugin name or path. Overrides it has no parameter for
// are an error, unless `used` is given: then the names it took are added there.
std::shared_ptr<const CurveScheme> load_curve(const std::string& name_or_path, const ParameterOverrides& overrides = {},
                                              std::set<std::string>* used = nullptr);

// "surface" or "curve": the kind of the scheme a name or path finds.
std::string scheme_kind(const std::string& name_or_path);

struct SchemeListing {
  std::string name, description, path, kind;  // kind: "surface" or "curve"
  // Where it comes from: "built-in", "SUBDIV_SCHEME_PATH", or "plugin NAME" (then `path` is
  // the plugin's file).
  std::string origin;
};
// Every scheme: files in the scheme directories and schemes registered in code (plugins),
// sorted by name.
std::vector<SchemeListing> list_schemes();

// Schemes in the JSON language given as text (plugins carry their JSON schemes this way);
// `label` names the text in messages as a file name would. Curve names resolve as in files.
std::shared_ptr<const Scheme> load_scheme_text(const std::string& text, const std::string& label,
                                               const ParameterOverrides& overrides = {});
std::shared_ptr<const CurveScheme> load_curve_text(const std::string& text, const std::string& label,
                                                   const ParameterOverrides& overrides = {},
                                                   std::set<std::string>* used = nullptr);

// A scheme defined in code (plugins, framework/plugin) instead of a file. It is found by
// name like a file in the scheme directories; the make functions build it for a set of
// --param overrides and throw subdiv::Error for bad values.
struct CodeSchemeEntry {
  std::string name, description;
  std::string kind;    // "surface" or "curve"
  std::string origin;  // "plugin NAME"
  std::string path;    // the plugin's file
  // Surface schemes: overrides it has no parameter for are an error.
  std::function<std::shared_ptr<const Scheme>(const ParameterOverrides&)> make_surface;
  // Curve schemes: the names of the overrides it took go to `used` (others may be meant for
  // the surface scheme that names this curve); with used == nullptr unknown ones are errors.
  std::function<std::shared_ptr<const CurveScheme>(const ParameterOverrides&, std::set<std::string>* used)> make_curve;
};
// Throws subdiv::Error when the name is taken by a scheme file or another code scheme.
void register_code_scheme(CodeSchemeEntry entry);
// Removes the most recently registered code scheme, which must have this name (the plugin
// loader undoes a refused plugin's registrations in reverse order).
void unregister_code_scheme(const std::string& name);
// Null when no code scheme has this name.
const CodeSchemeEntry* find_code_scheme(const std::string& name);

}  // namespace subdiv
