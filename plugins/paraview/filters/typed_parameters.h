#pragma once
// The typed widgets of the built-in schemes' parameters (scheme_parameter_widgets.py) send
// each value with its key "scheme:name"; the filters keep them here. Free of SubdivKit's
// headers: the filters' class headers, which ParaView's wrapper reads, hold one.
#include <map>
#include <string>

namespace subdiv {
namespace paraview {  // (VTK's wrapper tools read this header: no C++17 nested namespaces)

// The values of the typed parameter widgets (scheme_parameter_widgets.py), by scheme.
class TypedParameters {
public:
  // `key` is "scheme:name"; returns false when the value was already that.
  bool set(const std::string& key, const std::string& value);
  // The chosen scheme's values as "name=value ..." words, leaving out the names the
  // Parameters field's text `overriding` assigns: the field wins over the widgets (a name
  // given twice is refused, so both cannot go to SubdivKit).
  std::string words_for(const std::string& scheme, const std::string& overriding) const;

private:
  std::map<std::string, std::map<std::string, std::string>> values_;
};

}  // namespace paraview
}  // namespace subdiv
