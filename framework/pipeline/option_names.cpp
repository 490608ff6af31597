#include "framework/pipeline/option_names.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

template <class Value>
Value from_name(const std::vector<OptionChoice<Value>>& choices, std::string_view name, std::string_view option) {
  for (const auto& c : choices)
    if (name == c.name) return c.value;
  std::vector<std::string> listed;
  for (const auto& c : choices) listed.push_back(fmt::format("{} ({})", subdiv::quoted(c.name), c.meaning));
  const char* gap = option.ends_with('=') ? "" : " ";  // "boundary='x'" as Python writes it, "--boundary 'x'"
  throw Error(fmt::format("{}{}{}: choose one of {}", option, gap, subdiv::quoted(name), fmt::join(listed, ", ")));
}

template <class Value>
const char* name_of(const std::vector<OptionChoice<Value>>& choices, Value value) {
  for (const auto& c : choices)
    if (c.value == value) return c.name;
  return "unknown";
}

}  // namespace

const std::vector<OptionChoice<BoundaryInterpolation>>& boundary_choices() {
  static const std::vector<OptionChoice<BoundaryInterpolation>> choices = {
      {"edges-and-corners", BoundaryInterpolation::EdgesAndCorners, "boundary corners stay"},
      {"edges", BoundaryInterpolation::EdgesOnly, "corners follow the boundary curve"},
      {"none", BoundaryInterpolation::None, "no boundary rule: the surface stops short of the boundary"}};
  return choices;
}

const std::vector<OptionChoice<CreaseMethod>>& crease_method_choices() {
  static const std::vector<OptionChoice<CreaseMethod>> choices = {
      {"uniform", CreaseMethod::Uniform, "sharpness decreases by one per level"},
      {"chaikin", CreaseMethod::Chaikin, "sharpness averaged along the crease, as Chaikin's curve"}};
  return choices;
}

const std::vector<OptionChoice<FaceVaryingLinear>>& face_varying_choices() {
  // The names are face_varying_linear_name's: OBJ output writes the mode with them.
  static const std::vector<OptionChoice<FaceVaryingLinear>> choices = {
      {"none", FaceVaryingLinear::None, "smooth everywhere"},
      {"corners-only", FaceVaryingLinear::CornersOnly, "sharp corners"},
      {"corners-plus1", FaceVaryingLinear::CornersPlus1, "corners and junctions of seams"},
      {"corners-plus2", FaceVaryingLinear::CornersPlus2, "as corners-plus1, corners propagated"},
      {"boundaries", FaceVaryingLinear::Boundaries, "linear along seams and boundaries"},
      {"all", FaceVaryingLinear::All, "bilinear, OpenSubdiv's default"}};
  return choices;
}

BoundaryInterpolation boundary_from_name(std::string_view name, std::string_view option) {
  return from_name(boundary_choices(), name, option);
}

CreaseMethod crease_method_from_name(std::string_view name, std::string_view option) {
  return from_name(crease_method_choices(), name, option);
}

FaceVaryingLinear face_varying_from_name(std::string_view name, std::string_view option) {
  return from_name(face_varying_choices(), name, option);
}

const char* boundary_name(BoundaryInterpolation value) { return name_of(boundary_choices(), value); }
const char* crease_method_name(CreaseMethod value) { return name_of(crease_method_choices(), value); }

}  // namespace subdiv
