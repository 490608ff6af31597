#pragma once
// A geometry rule: the new point of one parent element (face, edge, vertex) as a weighted
// sum over neighbourhood roles. A term names a role, optionally a kind of new point of the
// same step (then each point of the role stands for that new point, expanded by the
// engine), and a weight formula evaluated for every point j of the role.
#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "framework/features/context.h"

namespace subdiv {

using Index = std::int32_t;

// The parent element a new point belongs to; numbered like OriginKind.
enum class Element : std::uint8_t { Vertex = 0, Edge = 1, Face = 2, Corner = 3 };
constexpr int kElementCount = 4;

enum class Role : std::uint8_t {
  Self,      // vertex rule: the vertex itself
  Ring,      // vertex rule: the other ends of the ring edges, CCW (j = 0..n-1)
  Faces,     // vertex or edge rule: incident faces, CCW (used with new face points)
  Edges,     // vertex or face rule: incident edges in ring/face order (new edge points)
  Ends,      // edge rule: the two end points
  Opposite,  // edge rule: in each incident triangle, the vertex off the edge
  Vertices,  // face rule: the face's vertices in order; corner rule: counted from the corner
  FaceCentroids,  // vertex rule: the centroid of each incident face (averaging passes)
  CreaseNeighbours,  // vertex crease rule: the vertices across the two sharp (or boundary) edges
  Diagonals,  // vertex rule: in each incident quad, the vertex opposite (f_i of Lin et al. 2015)
  Wings,     // edge rule: in each incident triangle, the vertex off the edge (= opposite)
  FarWings,  // edge rule: for each incident triangle (a, b, c), the vertices across (b, c) and (c, a)
  EndRing0,  // edge rule: the ring of the edge's first end, counted CCW from the edge (j = 0 is the other end)
  EndRing1,  // edge rule: the ring of the edge's second end, likewise
  Corners,   // face rule: the face's vertices, each seen with its own valence n (corner variables)
  CornerRings,  // face rule: each corner's ring, CCW from the face's previous vertex to its next
  EndSector0,  // edge rule: where end 0 is a feature vertex, the ring points p_0..p_m of its sector that
               // holds the edge, CCW from one feature edge to the next (empty elsewhere; sector variables)
  EndSector1,  // edge rule: the same for end 1
  Curve,     // crease and boundary rules: points along the feature curve (from the curve scheme)
  CreasePoint,  // vertex crease rule: the crease vertex Term::step crease edges along the crease
                // (negative: towards the nearest corner; in a rule for no particular distance, the
                // first crease neighbour's side)
};

enum class NewPoint : std::uint8_t { None, Face, Edge, Vertex };

struct Term {
  Role role = Role::Self;
  NewPoint new_point = NewPoint::None;
  std::string weight;  // formula text
  std::string where;   // place in the scheme file, for messages
  // Role::Curve only: fixed weights on points at offsets curve_start, curve_start + 1, ...
  // along the feature curve (vertex rules: 0 is the vertex; edge rules: 0 and 1 are the ends).
  int curve_start = 0;
  std::vector<std::string> curve_weights;
  // Role::CreasePoint only: how many crease edges along the crease, signed.
  int step = 0;
};

struct Rule {
  std::vector<Term> terms;
  std::string where;
};

// Rules by element and context; an empty optional means "use the engine default"
// (dart: the smooth rule; crease: the curve scheme's rule; corner: the vertex stays).
using RuleTable = std::array<std::array<std::optional<Rule>, kContextCount>, kElementCount>;

// Vertex crease rules chosen by a crease vertex's distance (in crease edges) from the nearest
// corner its crease ends at ("crease-ends" in a scheme file): by_distance[D], when set,
// replaces the `crease` rule at distance D; on a crease of exactly L edges between two corners
// by_length[L][D], when set, takes precedence (short creases, whose two ends' rules overlap).
// Entry 0 is never set (a corner uses the corner rule). Slot: std::optional<Rule> as loaded,
// CompiledRule once compiled.
template <class Slot>
struct CreaseEndTable {
  std::vector<Slot> by_distance;
  std::map<int, std::vector<Slot>> by_length;

  bool empty() const { return by_distance.empty() && by_length.empty(); }
  // How far along its crease a crease vertex looks for corners: the largest distance named,
  // and L - 1 for a crease of L edges (from the vertex next to one corner to the other).
  int search_reach() const {
    int reach = by_distance.empty() ? 0 : int(by_distance.size()) - 1;
    if (!by_length.empty()) reach = std::max(reach, by_length.rbegin()->first - 1);
    return reach;
  }
  // f(distance, length or 0, slot) for every slot, set or not.
  template <class F>
  void each(F&& f) const {
    for (size_t d = 0; d < by_distance.size(); ++d) f(int(d), 0, by_distance[d]);
    for (const auto& [length, slots] : by_length)
      for (size_t d = 0; d < slots.size(); ++d) f(int(d), length, slots[d]);
  }
};
using CreaseEndRules = CreaseEndTable<std::optional<Rule>>;
// The largest distance and the largest |step| a crease-end rule may name, and the longest
// crease (in edges between its corners) a rule for one length may name.
constexpr int kMaxCreaseReach = 24;
constexpr int kMaxCreaseLength = 2 * kMaxCreaseReach + 1;

// Roles registered at run time (plugins) take Role values from kFirstRegisteredRole up. A
// registered role lists parent vertices around one element in a canonical order; a term
// weights point j with its formula, like the built-in roles.
constexpr std::uint8_t kFirstRegisteredRole = 64;

struct Level;
struct RoleInfo {
  std::string name, description;
  Element element = Element::Vertex;  // the rules that may use it
  // Appends the role's points (parent vertex indices) around `element` of `level`: a vertex,
  // an edge, a face, or for corner rules the face, with `corner` its corner (else 0).
  std::function<void(const Level& level, Index element, int corner, std::vector<Index>& points)> points;
  // How many points it gives (at most) around an element of valence n with faces of k
  // sides; weight formulas are tabulated for j below max_points(largest n, largest k), and
  // `subdiv validate` checks weight sums with this count.
  std::function<int(int n, int k)> max_points;
  std::string origin = "built-in";
};

// Adds a role; throws subdiv::Error when the name is taken (built-in or registered), a
// function is missing or the roles run out (192 at most).
Role register_role(RoleInfo info);
// Removes the most recently registered role, which must be `role` (plugin loader rollback).
void unregister_role(Role role);
// The registered role, or null for a built-in one.
const RoleInfo* registered_role(Role role);
std::vector<const RoleInfo*> list_registered_roles();

std::string_view element_name(Element e);
std::string_view context_name(Context c);
std::string_view role_name(Role r);
std::optional<Role> role_from_name(std::string_view name);
std::optional<Context> context_from_name(std::string_view name);
std::optional<NewPoint> new_point_from_name(std::string_view name);
// Which roles a rule for this element may use.
bool role_allowed(Element element, Role role);

}  // namespace subdiv
