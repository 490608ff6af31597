#pragma once
// Finding and loading schemes by name or path.
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace subdiv {

class Scheme;
using ParameterOverrides = std::map<std::string, std::string>;

// `name_or_path` is a built-in scheme name (a file in the scheme directory) or a path
// to a .json file. Parameter overrides come from --param name=value.
std::shared_ptr<const Scheme> load_scheme(const std::string& name_or_path,
                                          const ParameterOverrides& overrides = {});

// The file a built-in name or a path stands for; throws with the known names if none.
std::string scheme_file_path(const std::string& name_or_path);

struct SchemeListing {
  std::string name, description, path, kind;  // kind: "surface" or "curve"
};
std::vector<SchemeListing> list_schemes();

}  // namespace subdiv
