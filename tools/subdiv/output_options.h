#pragma once
// How `subdiv refine` writes ParaView files (.vtp, .pvd, .pvtp): which of SubdivKit's own
// arrays they hold (--arrays) and how they are compressed (--compression,
// --compression-level). Mesh formats (.obj, .off, .ply, .stl) hold none of these arrays.
#include <CLI/CLI.hpp>
#include <set>
#include <string>
#include <vector>

#include "framework/io/vtk/vtk_output.h"

namespace subdiv::cli {

// SubdivKit's arrays: point origin, valence, level, vertex_class, corner_sharpness; cell
// parent_face, base_face, sharpness, cell_kind (README's table says what each holds). The
// user's own arrays and those --limit and --normals add are always written.
class ArraySelection {
public:
  static ArraySelection all();
  // base_face, cell_kind, sharpness, corner_sharpness: what the cells are (faces, polylines,
  // creases), their features, and the input face each refined face lies in. They need only
  // the last level's faces, so that level can be built without edges and vertex rings
  // (RefineOptions::faces_only_last_level); valence and vertex_class need those.
  static ArraySelection defaults();
  // A comma list of names, "default" and "all", or "none" alone; throws subdiv::Error naming
  // --arrays and listing the names for anything else.
  static ArraySelection parse(const std::string& text);

  bool has(const std::string& name) const { return names_.count(name) > 0; }
  // valence or vertex_class: read off the last level's edges and vertex rings.
  bool needs_last_level_edges() const { return has("valence") || has("vertex_class"); }
  // The arrays write_vtp adds itself (sharpness, cell_kind, corner_sharpness) as chosen.
  VtkWriteOptions vtk_options(VtkWriteOptions options) const;

private:
  std::set<std::string> names_;
};

// Every name --arrays takes, in README's order.
const std::vector<std::string>& output_array_names();

struct OutputArgs {
  std::string arrays = "default";
  std::string compression = "lz4";
  int compression_level = 1;
  std::string vtp_encoding = "base64";
};

void add_output_options(CLI::App* cmd, OutputArgs& args);

// Throws subdiv::Error naming the option for a bad --arrays, --compression or --vtp-encoding.
struct OutputChoice {
  ArraySelection arrays = ArraySelection::all();
  VtkWriteOptions vtk;  // compression, and write_vtp's own arrays as `arrays` says
};
OutputChoice output_choice(const OutputArgs& args);

}  // namespace subdiv::cli
