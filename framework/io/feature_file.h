#pragma once
// Feature sidecar files (`subdiv refine --features FILE.json`): creases and corners for a
// mesh, by 0-based vertex index, kept apart from the mesh file so that any format can carry
// them. The format (docs/features.md):
//
//   {
//     "creases": [
//       {"edge": [0, 1], "sharpness": 2.5},
//       {"path": [4, 5, 6, 7, 4], "sharpness": "infinite"},
//       {"path": [8, 9, 10]}
//     ],
//     "corners": [
//       {"vertex": 3, "sharpness": 10},
//       {"vertices": [11, 12], "sharpness": 0.5}
//     ],
//     "holes": [3, 7]
//   }
//
// - "edge" names one edge by its two end points; "path" names the edges between
//   consecutive vertices of a walk along the mesh (repeat the first vertex to close a loop).
// - "vertex" tags one vertex, "vertices" several.
// - "holes" lists faces (0-based) that are refined and shape their neighbours but are left
//   out of the surface, as OpenSubdiv's hole tag.
// - "sharpness" is a number >= 0 (0 smooth, 10 or more infinitely sharp) or the string
//   "infinite"; it may be left out and then means infinitely sharp.
// - Both lists are optional; "description" and "$schema" are allowed for humans and editors.
//   Any other key is refused, so that a misspelt key is not silently ignored.
// - Tags apply after those of the mesh file and replace them on the same edge or vertex; a
//   later entry replaces an earlier one.
#include <filesystem>
#include <string>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

struct FeatureTags {
  struct Crease {
    Index v0, v1;
    float sharpness;
    std::string where;  // e.g. "creases[2].path[3..4]", for messages
  };
  struct Corner {
    Index v;
    float sharpness;
    std::string where;
  };
  std::string source;  // the file, for messages
  std::vector<Crease> creases;
  std::vector<Corner> corners;
  struct Hole {
    Index face;
    std::string where;
  };
  std::vector<Hole> holes;
};

// Reads and checks a feature file. Throws subdiv::Error naming the file: "FILE:LINE:COL:
// malformed JSON: ..." for syntax errors, "FILE: creases[2].sharpness: ..." for entries
// that are not as described above (negative or non-numeric sharpness, a vertex index that
// is not a whole number >= 0, an "edge" without two distinct vertices, unknown keys).
FeatureTags read_feature_file(const std::filesystem::path& file);

// Parses feature JSON held in memory; `source` names it in messages.
FeatureTags parse_feature_json(const std::string& text, const std::string& source);

// Sets the tags on the level's edges and vertices. Throws subdiv::Error naming the file and
// the entry when a crease names two vertices that no edge joins or a vertex is out of range;
// the level is unchanged then.
void apply_feature_tags(const FeatureTags& tags, Level& level);

}  // namespace subdiv
