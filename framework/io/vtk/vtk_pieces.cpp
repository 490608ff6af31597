#include "framework/io/vtk/vtk_pieces.h"

#include <fmt/format.h>
#include <fstream>
#include <regex>
#include <system_error>
#include <vector>

#include <vtkPolyData.h>

#include "framework/io/vtk/vtk_polydata.h"
#include "framework/util/buffered_output.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace fs = std::filesystem;

namespace {

std::string folder_name(const fs::path& pvtp) { return pvtp.stem().string() + "_pieces"; }

// The markup of a .vtp up to its appended data, one tag a line: the text between tags
// (inline base64 arrays, the whole file with the default encoding: 400 MB for a piece of
// level 3 of a 1M-quad mesh) is skipped as it is read, not kept and searched.
std::string xml_head(const fs::path& vtp) {
  std::ifstream in(vtp, std::ios::binary);
  if (!in) throw Error(fmt::format("cannot read piece {} to describe it in the .pvtp", subdiv::quoted(vtp.string())));
  std::string head;
  std::vector<char> chunk(size_t(1) << 20);
  bool in_tag = false;
  while (in.read(chunk.data(), std::streamsize(chunk.size())) || in.gcount() > 0) {
    for (const char* c = chunk.data(); c != chunk.data() + in.gcount(); ++c) {
      if (!in_tag && *c != '<') continue;
      in_tag = *c != '>';
      head += *c;
      if (in_tag) continue;
      if (head.find("<AppendedData", head.rfind('\n') + 1) != std::string::npos) return head;
      head += '\n';
    }
  }
  return head;
}

// The <DataArray .../> declarations inside <Section>...</Section> of a .vtp head, as the
// <PDataArray .../> a .pvtp declares: type, name and components, no data.
std::string parallel_arrays(const std::string& head, const std::string& section) {
  const size_t begin = head.find("<" + section + ">"), end = head.find("</" + section + ">");
  if (begin == std::string::npos || end == std::string::npos) return "";
  const std::string body = head.substr(begin, end - begin);
  static const std::regex array("<DataArray([^>]*)>");
  static const std::regex attribute("\\s(type|Name|NumberOfComponents)=\"([^\"]*)\"");
  std::string out;
  for (auto a = std::sregex_iterator(body.begin(), body.end(), array); a != std::sregex_iterator(); ++a) {
    const std::string attributes = (*a)[1];
    std::string kept;
    for (auto t = std::sregex_iterator(attributes.begin(), attributes.end(), attribute); t != std::sregex_iterator(); ++t)
      kept += fmt::format(" {}=\"{}\"", (*t)[1].str(), escaped((*t)[2].str()));
    out += fmt::format("      <PDataArray{}/>\n", kept);
  }
  return out;
}

}  // namespace

fs::path piece_file(const fs::path& pvtp, int piece) {
  return pvtp.parent_path() / folder_name(pvtp) / fmt::format("piece_{}.vtp", piece);
}

std::string piece_source(const fs::path& pvtp, int piece) {
  return fmt::format("{}/piece_{}.vtp", folder_name(pvtp), piece);
}

void make_piece_folder(const fs::path& pvtp) {
  const fs::path dir = piece_file(pvtp, 0).parent_path();
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir, ec))
    throw Error(fmt::format("cannot write {}: cannot create the pieces' folder {} ({}); check the path and its "
                            "permissions",
                            subdiv::quoted(pvtp.string()), subdiv::quoted(dir.string()), ec ? ec.message() : "a file of that name exists"));
}

void write_piece_vtp(StagedFiles& staged, const fs::path& target, const OutputLevel& level,
                     const VtkWriteOptions& options) {
  const io_detail::LevelCheck check = io_detail::check_output_level(
      level, fmt::format("cannot write {}", subdiv::quoted(target.string())), io_detail::IntegerValues::WhenConverted);
  const auto poly = io_detail::make_polydata(level, options, io_detail::LevelMemory::Share, &check);
  io_detail::write_polydata_file(*poly, staged.stage(target), target, options);
}

void write_pvtp(const fs::path& pvtp, int pieces) {
  const std::string head = xml_head(piece_file(pvtp, 0));
  write_file_atomically(pvtp, [&](const fs::path& tmp) {
    BufferedOutput out(tmp, pvtp);
    out.print("<?xml version=\"1.0\"?>\n"
              "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
              "  <PPolyData GhostLevel=\"0\">\n");
    out.print("    <PPointData>\n{}    </PPointData>\n", parallel_arrays(head, "PointData"));
    out.print("    <PCellData>\n{}    </PCellData>\n", parallel_arrays(head, "CellData"));
    out.print("    <PPoints>\n{}    </PPoints>\n", parallel_arrays(head, "Points"));
    for (int i = 0; i < pieces; ++i) out.print("    <Piece Source=\"{}\"/>\n", piece_source(pvtp, i));
    out.print("  </PPolyData>\n</VTKFile>\n");
    out.close();
  });
}

}  // namespace subdiv
