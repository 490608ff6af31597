#pragma once
// The shape options' names, one table for every front-end: the command line's choices and
// help, Python's keyword values and the ParaView filter's menus all read them from here.
// The names are OpenSubdiv's where it has the option (Sdc::Options), lower-case with dashes.
#include <string>
#include <string_view>
#include <vector>

#include "framework/features/feature_options.h"
#include "framework/primvar/face_varying.h"

namespace subdiv {

// One choice of an option: its name and what it does, for help texts.
template <class Value>
struct OptionChoice {
  const char* name;
  Value value;
  const char* meaning;
};

// Boundary interpolation: edges-and-corners (boundary corners stay), edges (corners follow
// the boundary curve), none (boundary faces are holes' rims: not refined into the limit).
const std::vector<OptionChoice<BoundaryInterpolation>>& boundary_choices();
// How semi-sharp crease sharpness decays: uniform, chaikin.
const std::vector<OptionChoice<CreaseMethod>>& crease_method_choices();
// Face-varying data's linear interpolation: none, corners-only, corners-plus1, corners-plus2,
// boundaries, all (OpenSubdiv's default).
const std::vector<OptionChoice<FaceVaryingLinear>>& face_varying_choices();

// The value named `name`; throws subdiv::Error "<option> '<name>': choose one of ..." where
// `option` is the option as the caller's user spells it ("--boundary", "boundary=").
BoundaryInterpolation boundary_from_name(std::string_view name, std::string_view option = "boundary");
CreaseMethod crease_method_from_name(std::string_view name, std::string_view option = "crease method");
FaceVaryingLinear face_varying_from_name(std::string_view name, std::string_view option = "face-varying boundary");

const char* boundary_name(BoundaryInterpolation value);
const char* crease_method_name(CreaseMethod value);

// The names of a table, in order, for help texts and checks.
template <class Value>
std::vector<std::string> choice_names(const std::vector<OptionChoice<Value>>& choices) {
  std::vector<std::string> names;
  for (const auto& c : choices) names.emplace_back(c.name);
  return names;
}

}  // namespace subdiv
