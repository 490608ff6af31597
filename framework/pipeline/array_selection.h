#pragma once
// Which of SubdivKit's own arrays a described level carries: how each vertex was made
// (origin), its valence, level and feature class (vertex_class), a corner's sharpness, and
// per cell its parent face, the input face it lies in (base_face), a crease's sharpness and
// what the cell is (cell_kind). The user's own arrays are always carried.
#include <set>
#include <string>
#include <vector>

namespace subdiv {

class ArraySelection {
public:
  static ArraySelection all();
  // base_face, cell_kind, sharpness, corner_sharpness: what the cells are (faces, polylines,
  // creases), their features, and the input face each refined face lies in. They need only
  // the last level's faces, so that level can be built without edges and vertex rings
  // (RefineOptions::faces_only_last_level); valence and vertex_class need those.
  static ArraySelection defaults();
  // A comma list of names, "default" and "all", or "none" alone; throws subdiv::Error
  // listing the names for anything else.
  static ArraySelection parse(const std::string& text);

  bool has(const std::string& name) const { return names_.count(name) > 0; }
  // valence or vertex_class: read off the last level's edges and vertex rings.
  bool needs_last_level_edges() const { return has("valence") || has("vertex_class"); }

private:
  std::set<std::string> names_;
};

// Every name ArraySelection::parse takes, in README's order.
const std::vector<std::string>& output_array_names();
// The names of ArraySelection::defaults().
const std::vector<std::string>& default_array_names();

}  // namespace subdiv
