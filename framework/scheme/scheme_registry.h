#pragma once
// Finding and loading schemes by name or path.
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace subdiv {

class Scheme;
struct CurveScheme;
using ParameterOverrides = std::map<std::string, std::string>;

// `name_or_path` is a built-in scheme name (a file in the scheme directory) or a path
// to a .json file. Parameter overrides come from --param name=value.
std::shared_ptr<const Scheme> load_scheme(const std::string& name_or_path,
                                          const ParameterOverrides& overrides = {});

// A curve scheme by built-in name or path. Throws subdiv::Error for a surface scheme or an
// override the curve scheme has no parameter for.
std::shared_ptr<const CurveScheme> load_curve(const std::string& name_or_path,
                                              const ParameterOverrides& overrides = {});

// "surface" or "curve": the kind of the scheme a name or path finds.
std::string scheme_kind(const std::string& name_or_path);

struct SchemeListing {
  std::string name, description, path, kind;  // kind: "surface" or "curve"
};
std::vector<SchemeListing> list_schemes();

}  // namespace subdiv
