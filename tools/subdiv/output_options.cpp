#include "output_options.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv::cli {
namespace {

struct CompressorName {
  const char* name;
  VtkCompressor type;
};
const CompressorName kCompressors[] = {{"zlib", VtkCompressor::ZLib},
                                       {"lz4", VtkCompressor::LZ4},
                                       {"lzma", VtkCompressor::LZMA},
                                       {"none", VtkCompressor::None}};

std::string compressor_names() {
  std::vector<std::string> names;
  for (const auto& c : kCompressors) names.push_back(c.name);
  return fmt::format("{}", fmt::join(names, ", "));
}

VtkCompressor compressor_from_name(const std::string& name) {
  for (const auto& c : kCompressors)
    if (name == c.name) return c.type;
  throw Error(fmt::format("--compression {} is not a compressor; use one of {}", subdiv::quoted(name), compressor_names()));
}

VtkEncoding encoding_from_name(const std::string& name) {
  if (name == "base64") return VtkEncoding::Base64;
  if (name == "raw") return VtkEncoding::Raw;
  throw Error(fmt::format("--vtp-encoding {} is not an encoding; use base64 or raw", subdiv::quoted(name)));
}

// The arrays write_vtp adds itself (sharpness, cell_kind, corner_sharpness) as `arrays` chooses.
VtkWriteOptions vtk_options(const ArraySelection& arrays, VtkWriteOptions options) {
  options.sharpness = arrays.has("sharpness");
  options.cell_kind = arrays.has("cell_kind");
  options.corner_sharpness = arrays.has("corner_sharpness");
  return options;
}

}  // namespace

void add_output_options(CLI::App* cmd, OutputArgs& args) {
  cmd->add_option("--arrays", args.arrays,
                  fmt::format("SubdivKit's arrays in .vtp/.pvd/.pvtp output: a comma list of {}; or default ({}: they "
                              "need only the last level's faces, which is faster), all, none. The mesh's own arrays "
                              "are always written; .obj/.off/.ply/.stl hold none of these",
                              fmt::join(output_array_names(), ", "), fmt::join(default_array_names(), ",")))
      ->capture_default_str();
  cmd->add_option("--compression", args.compression,
                  fmt::format("Compressor of .vtp/.pvd/.pvtp output: {} (VTK's; ParaView reads them all). lz4, the "
                              "default, is fast with files half the size of none's; none writes fastest (about "
                              "two thirds of lz4's time) but the largest files; zlib files are about 2.6 times "
                              "smaller than lz4's and take 3 times as long to write; lzma smaller still and much "
                              "slower",
                              compressor_names()))
      ->capture_default_str();
  cmd->add_option("--compression-level", args.compression_level,
                  "1 (fastest) to 9 (smallest), as VTK takes it (lz4: acceleration 10 - level)")
      ->check(CLI::Range(1, 9))
      ->capture_default_str();
  cmd->add_option("--vtp-encoding", args.vtp_encoding,
                  "How .vtp/.pvd/.pvtp output holds its arrays: base64 (inline base64 text, the default: every "
                  "ParaView reads it) or raw (raw appended binary after the XML: a quarter smaller and faster to "
                  "write, but VTK before 9.3, e.g. Debian 12's ParaView 5.11, cannot read it; VTK 9.3 and later and "
                  "SubdivKit's own readers, subdiv included, can)")
      ->capture_default_str();
}

OutputChoice output_choice(const OutputArgs& args) {
  OutputChoice choice;
  try {
    choice.arrays = ArraySelection::parse(args.arrays);
  } catch (const Error& e) {
    throw Error(fmt::format("--{}", e.what()));  // the library names the option "arrays"
  }
  choice.vtk.compressor = compressor_from_name(args.compression);
  choice.vtk.compression_level = args.compression_level;
  choice.vtk.encoding = encoding_from_name(args.vtp_encoding);
  choice.vtk = vtk_options(choice.arrays, choice.vtk);
  return choice;
}

}  // namespace subdiv::cli
