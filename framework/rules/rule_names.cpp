// The names the scheme language uses for elements, contexts, roles and new points.
#include "framework/rules/rule.h"

namespace subdiv {
namespace {

constexpr std::array<std::pair<Role, std::string_view>, 15> kRoleNames{{
    {Role::Self, "self"},
    {Role::Ring, "ring"},
    {Role::Faces, "faces"},
    {Role::Edges, "edges"},
    {Role::Ends, "ends"},
    {Role::Opposite, "opposite"},
    {Role::Vertices, "vertices"},
    {Role::FaceCentroids, "face-centroids"},
    {Role::CreaseNeighbours, "crease-neighbours"},
    {Role::Diagonals, "diagonals"},
    {Role::Wings, "wings"},
    {Role::FarWings, "far-wings"},
    {Role::EndRing0, "end-ring-0"},
    {Role::EndRing1, "end-ring-1"},
    {Role::Curve, "curve"},
}};

}  // namespace

std::string_view element_name(Element e) {
  constexpr std::string_view names[] = {"vertex", "edge", "face", "corner"};
  return names[int(e)];
}

std::string_view context_name(Context c) {
  constexpr std::string_view names[] = {"smooth", "dart", "crease", "corner"};
  return names[int(c)];
}

std::string_view role_name(Role r) {
  for (auto& [role, name] : kRoleNames)
    if (role == r) return name;
  return "?";
}

std::optional<Role> role_from_name(std::string_view name) {
  for (auto& [role, n] : kRoleNames)
    if (n == name) return role;
  return std::nullopt;
}

std::optional<Context> context_from_name(std::string_view name) {
  for (int c = 0; c < kContextCount; ++c)
    if (context_name(Context(c)) == name) return Context(c);
  return std::nullopt;
}

std::optional<NewPoint> new_point_from_name(std::string_view name) {
  if (name == "face") return NewPoint::Face;
  if (name == "edge") return NewPoint::Edge;
  if (name == "vertex") return NewPoint::Vertex;
  return std::nullopt;
}

bool role_allowed(Element element, Role role) {
  switch (element) {
    case Element::Vertex:
      return role == Role::Self || role == Role::Ring || role == Role::Faces ||
             role == Role::Edges || role == Role::FaceCentroids || role == Role::CreaseNeighbours || role == Role::Diagonals ||
             role == Role::Curve;
    case Element::Edge:
      return role == Role::Ends || role == Role::Faces || role == Role::Opposite ||
             role == Role::Wings || role == Role::FarWings || role == Role::EndRing0 ||
             role == Role::EndRing1 || role == Role::Curve;
    case Element::Face:
      return role == Role::Vertices || role == Role::Edges;
    case Element::Corner:
      return role == Role::Self || role == Role::Vertices || role == Role::Curve;
  }
  return false;
}

}  // namespace subdiv
