// The names the scheme language uses for elements, contexts, roles and new points.
#include <deque>
#include <fmt/format.h>
#include <mutex>

#include "framework/rules/rule.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

constexpr std::array<std::pair<Role, std::string_view>, 20> kRoleNames{{
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
    {Role::Corners, "corners"},
    {Role::CornerRings, "corner-rings"},
    {Role::EndSector0, "end-sector-0"},
    {Role::EndSector1, "end-sector-1"},
    {Role::Curve, "curve"},
    {Role::CreasePoint, "crease-point"},
}};

// Registered roles (plugins); a deque keeps references stable while roles are added.
struct RoleTable {
  std::mutex mutex;
  std::deque<RoleInfo> roles;
};

RoleTable& role_table() {
  static RoleTable t;
  return t;
}

}  // namespace

Role register_role(RoleInfo info) {
  if (info.name.empty()) throw Error("a role needs a name");
  if (!info.points || !info.max_points) throw Error(fmt::format("role {} needs both functions: points and max_points", subdiv::quoted(info.name)));
  for (auto& [role, name] : kRoleNames)
    if (name == info.name) throw Error(fmt::format("a role named {} is built in", subdiv::quoted(info.name)));
  RoleTable& t = role_table();
  std::lock_guard lock(t.mutex);
  for (const auto& r : t.roles)
    if (r.name == info.name) throw Error(fmt::format("a role named {} already exists ({})", subdiv::quoted(info.name), r.origin));
  if (t.roles.size() >= 256 - kFirstRegisteredRole) throw Error("too many registered roles");
  t.roles.push_back(std::move(info));
  return Role(kFirstRegisteredRole + t.roles.size() - 1);
}

void unregister_role(Role role) {
  RoleTable& t = role_table();
  std::lock_guard lock(t.mutex);
  if (t.roles.empty() || size_t(std::uint8_t(role)) != kFirstRegisteredRole + t.roles.size() - 1)
    throw Error("unregister_role: only the most recently registered role can be removed");
  t.roles.pop_back();
}

const RoleInfo* registered_role(Role role) {
  if (std::uint8_t(role) < kFirstRegisteredRole) return nullptr;
  RoleTable& t = role_table();
  std::lock_guard lock(t.mutex);
  const size_t i = std::uint8_t(role) - kFirstRegisteredRole;
  return i < t.roles.size() ? &t.roles[i] : nullptr;
}

std::vector<const RoleInfo*> list_registered_roles() {
  RoleTable& t = role_table();
  std::lock_guard lock(t.mutex);
  std::vector<const RoleInfo*> out;
  for (const auto& r : t.roles) out.push_back(&r);
  return out;
}

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
  if (const RoleInfo* info = registered_role(r)) return info->name;
  return "?";
}

std::optional<Role> role_from_name(std::string_view name) {
  for (auto& [role, n] : kRoleNames)
    if (n == name) return role;
  RoleTable& t = role_table();
  std::lock_guard lock(t.mutex);
  for (size_t i = 0; i < t.roles.size(); ++i)
    if (t.roles[i].name == name) return Role(kFirstRegisteredRole + i);
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
  if (const RoleInfo* info = registered_role(role)) return info->element == element;
  switch (element) {
    case Element::Vertex:
      return role == Role::Self || role == Role::Ring || role == Role::Faces ||
             role == Role::Edges || role == Role::FaceCentroids || role == Role::CreaseNeighbours || role == Role::Diagonals ||
             role == Role::Curve || role == Role::CreasePoint;
    case Element::Edge:
      return role == Role::Ends || role == Role::Faces || role == Role::Opposite ||
             role == Role::Wings || role == Role::FarWings || role == Role::EndRing0 ||
             role == Role::EndRing1 || role == Role::EndSector0 || role == Role::EndSector1 || role == Role::Curve;
    case Element::Face:
      return role == Role::Vertices || role == Role::Edges || role == Role::Corners || role == Role::CornerRings;
    case Element::Corner:
      return role == Role::Self || role == Role::Vertices || role == Role::Curve;
  }
  return false;
}

}  // namespace subdiv
