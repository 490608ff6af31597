// Splits by name: the built-in splitters and those registered at run time (plugins).
#include <cmath>
#include <deque>
#include <fmt/format.h>
#include <mutex>

#include "framework/refine/splitter.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

SplitterInfo builtin(std::string name, std::string description, SplitResult (*fn)(const Level&),
                     std::vector<OriginKind> rule_elements) {
  SplitterInfo info;
  info.name = std::move(name);
  info.description = std::move(description);
  info.split = [fn](const Level& parent, int) { return fn(parent); };
  info.rule_elements = std::move(rule_elements);
  return info;
}

// Splitters by id: the built-in ones at their SplitKind values, registered ones from
// kFirstRegisteredSplit. A deque keeps references stable while splitters are added.
struct SplitterTable {
  std::mutex mutex;
  std::deque<SplitterInfo> builtins, registered;

  SplitterTable() {
    using O = OriginKind;
    SplitterInfo quad = builtin("quad", "primal 1-to-k split of any polygon: new face and edge points", split_quad,
                                {O::Vertex, O::Edge, O::Face});
    quad.split_faces_only = [](const Level& parent, int) { return split_quad_faces(parent); };
    quad.engine_propagates_tags = true;
    quad.handles_non_manifold = true;
    SplitterInfo tri = builtin("triangle", "primal 1-to-4 split of triangles: new edge points", split_triangle,
                               {O::Vertex, O::Edge});
    tri.split_faces_only = [](const Level& parent, int) { return split_triangle_faces(parent); };
    tri.required_face_size = 3;
    tri.engine_propagates_tags = true;
    tri.handles_non_manifold = true;
    SplitterInfo sqrt3;
    sqrt3.name = "sqrt3";
    sqrt3.description = "sqrt(3) split (Kobbelt 2000): face points, old edges flipped; boundaries trisected every second step";
    sqrt3.split = split_sqrt3;
    sqrt3.split_faces_only = split_sqrt3_faces;
    sqrt3.rule_elements = {O::Vertex, O::Face};
    sqrt3.required_face_size = 3;
    sqrt3.curve_arity = 3;
    sqrt3.scale = std::sqrt(3.0);
    sqrt3.period = 2;          // the split turns the mesh by 30 degrees
    sqrt3.feature_period = 2;  // boundaries are trisected every second step
    sqrt3.handles_non_manifold = true;  // non-manifold edges kept as creases, with a warning (sqrt3_split.cpp)
    SplitterInfo dual = builtin("dual", "dual split (Doo and Sabin 1978): one new point per face corner", split_dual, {O::Corner});
    dual.split_faces_only = [](const Level& parent, int) { return split_dual_faces(parent); };
    dual.primal = false;
    dual.handles_non_manifold = true;  // with a gap and a warning (dual_split.cpp)
    SplitterInfo mid = builtin("mid-edge", "mid-edge split (Peters and Reif 1997): one new point per edge", split_mid_edge, {O::Edge});
    mid.split_faces_only = [](const Level& parent, int) { return split_mid_edge_faces(parent); };
    mid.primal = false;
    mid.scale = std::sqrt(2.0);
    mid.period = 2;  // the split turns the mesh by 45 degrees
    mid.handles_non_manifold = true;
    quad.topology_reach = tri.topology_reach = 0.5;
    sqrt3.topology_reach = mid.topology_reach = 1.5;
    // A dual split's faces near a vertex depend on the vertex's class (its sharp edges and
    // boundary, features/dual_features.h), which reads the vertex's whole ring: one ring more
    // than the faces around it.
    dual.topology_reach = 2.5;
    mid.ring_scale = 1.0;
    for (SplitterInfo* info : {&quad, &tri, &sqrt3, &dual, &mid}) builtins.push_back(std::move(*info));
  }

  const SplitterInfo* find(std::string_view name, SplitKind* kind) {
    for (size_t i = 0; i < builtins.size(); ++i)
      if (builtins[i].name == name) return *kind = SplitKind(i), &builtins[i];
    for (size_t i = 0; i < registered.size(); ++i)
      if (registered[i].name == name) return *kind = SplitKind(kFirstRegisteredSplit + i), &registered[i];
    return nullptr;
  }
};

SplitterTable& table() {
  static SplitterTable t;
  return t;
}

}  // namespace

const SplitterInfo& splitter_info(SplitKind kind) {
  SplitterTable& t = table();
  std::lock_guard lock(t.mutex);
  const size_t id = size_t(kind);
  if (id < t.builtins.size()) return t.builtins[id];
  if (id >= kFirstRegisteredSplit && id - kFirstRegisteredSplit < t.registered.size())
    return t.registered[id - kFirstRegisteredSplit];
  throw Error(fmt::format("unknown split id {}", id));
}

SplitResult split(SplitKind kind, const Level& parent, int step_index, bool faces_only) {
  const SplitterInfo& info = splitter_info(kind);
  if (faces_only && info.split_faces_only) return info.split_faces_only(parent, step_index);
  return info.split(parent, step_index);
}

SplitKind split_kind_from_name(std::string_view name) {
  SplitterTable& t = table();
  std::lock_guard lock(t.mutex);
  SplitKind kind{};
  if (t.find(name, &kind)) return kind;
  std::string known;
  for (const auto* list : {&t.builtins, &t.registered})
    for (const auto& info : *list) known += (known.empty() ? "" : ", ") + info.name;
  throw Error(fmt::format("unknown split {}; the splits are: {}", subdiv::quoted(name), known));
}

SplitKind register_splitter(SplitterInfo info) {
  SplitterTable& t = table();
  std::lock_guard lock(t.mutex);
  if (info.name.empty()) throw Error("a splitter needs a name");
  if (!info.split) throw Error(fmt::format("splitter {} has no split function", subdiv::quoted(info.name)));
  if (info.curve_arity < 2) throw Error(fmt::format("splitter {}: curve_arity must be 2 or more", subdiv::quoted(info.name)));
  if (info.required_face_size != 0 && info.required_face_size < 3)
    throw Error(fmt::format("splitter {}: required_face_size must be 0 (any) or 3 or more", subdiv::quoted(info.name)));
  SplitKind existing{};
  if (const SplitterInfo* other = t.find(info.name, &existing))
    throw Error(fmt::format("a splitter named {} already exists ({})", subdiv::quoted(info.name), other->origin));
  t.registered.push_back(std::move(info));
  return SplitKind(kFirstRegisteredSplit + t.registered.size() - 1);
}

void unregister_splitter(SplitKind kind) {
  SplitterTable& t = table();
  std::lock_guard lock(t.mutex);
  if (t.registered.empty() || size_t(kind) != kFirstRegisteredSplit + t.registered.size() - 1)
    throw Error("unregister_splitter: only the most recently registered splitter can be removed");
  t.registered.pop_back();
}

}  // namespace subdiv
