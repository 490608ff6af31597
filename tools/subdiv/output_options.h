#pragma once
// How `subdiv refine` writes ParaView files (.vtp, .pvd, .pvtp): which of SubdivKit's own
// arrays they hold (--arrays) and how they are compressed (--compression,
// --compression-level). Mesh formats (.obj, .off, .ply, .stl) hold none of these arrays.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "framework/io/vtk/vtk_output.h"
#include "framework/pipeline/array_selection.h"

namespace subdiv::cli {

struct OutputArgs {
  std::string arrays = "default";
  std::string compression = "lz4";
  int compression_level = 1;
  std::string vtp_encoding = "base64";
};

void add_output_options(CLI::App* cmd, OutputArgs& args);

struct OutputChoice {
  ArraySelection arrays = ArraySelection::all();
  VtkWriteOptions vtk;  // compression, and write_vtp's own arrays as `arrays` says
};
// Throws subdiv::Error naming the option for a bad --arrays, --compression or --vtp-encoding.
OutputChoice output_choice(const OutputArgs& args);

}  // namespace subdiv::cli
