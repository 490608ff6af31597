#pragma once
// Plugin splitters and roles as the engine calls them, guarded like plugin rules
// (checked_rules.h): whatever a plugin's split, points or max_points function throws becomes
// a subdiv::Error naming the plugin, its file and the function, and what it returns is
// checked before the engine reads it (every index in range, every array of the size its
// level needs), so a broken plugin gets a message instead of a crash or garbage.
// Internal to plugin/.
#include <string>

#include "framework/refine/splitter.h"
#include "framework/rules/rule.h"

namespace subdiv {

// The problem with a split's result, or empty: sizes, offsets and every index of the child
// level and the origins within range and consistent (a corner's edge joins its vertex to the
// next, an edge's faces hold it, a ring's edges and faces hold its vertex). `faces_only`:
// the result of split_faces_only (faces and origins only). `propagates_tags`: the engine
// reads the child's vertex v as parent vertex v and V + e as edge e's new point.
std::string split_result_problem(const Level& parent, const SplitResult& result, bool faces_only,
                                 bool propagates_tags);

// `who` names the plugin and its file, e.g. "plugin 'quads' (/p/quads.so)".
SplitterInfo checked_splitter(SplitterInfo info, const std::string& who);
RoleInfo checked_role(RoleInfo info, const std::string& who);

// The most points a role may give (weight tables are tabulated up to it).
constexpr int kMaxRolePoints = 65536;

}  // namespace subdiv
