#include "framework/io/vtk/vtk_output.h"

#include <regex>
#include <set>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <vtkPolyData.h>

#include "framework/io/vtk/vtk_polydata.h"
#include "framework/io/vtk/vtk_xml_text.h"
#include "framework/util/atomic_file.h"
#include "framework/util/buffered_output.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace fs = std::filesystem;

namespace {

struct Entry {
  int level;
  std::string file;  // relative to the .pvd, with '/' separators
};

void write_collection(const fs::path& file, const fs::path& shown, const std::vector<Entry>& entries) {
  BufferedOutput out(file, shown);
  out.print("<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            "  <Collection>\n");
  for (const Entry& e : entries)
    out.print("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", e.level,
              io_detail::xml_attribute_text(e.file));
  out.print("  </Collection>\n</VTKFile>\n");
  out.close();
}

// Each level's check, in order (io_detail::check_output_level): every level, before any file.
std::vector<io_detail::LevelCheck> check_levels(std::span<const OutputLevel> levels, std::string_view context) {
  if (levels.empty()) throw Error(fmt::format("{}: there are no levels to write", context));
  std::set<int> seen;
  std::vector<io_detail::LevelCheck> checks;
  for (const OutputLevel& level : levels) {
    if (!seen.insert(level.level).second)
      throw Error(fmt::format("{}: level {} appears twice; every level needs its own number",
                              context, level.level));
    checks.push_back(io_detail::check_output_level(level, fmt::format("{} (level {})", context, level.level)));
  }
  return checks;
}

// Creates the level directory if needed; returns whether it did, so that a failed write
// can remove it again.
bool make_directory(const fs::path& dir, std::string_view context) {
  std::error_code ec;
  const bool created = fs::create_directory(dir, ec);
  if (ec || !fs::is_directory(dir, ec))
    throw Error(fmt::format("{}: cannot create directory {} ({})", context, subdiv::quoted(dir.string()),
                            ec ? ec.message() : "a file of that name exists"));
  return created;
}

// The level files of an earlier run that wrote more levels (or others) into the same folder:
// the index no longer lists them, so they would only mislead. Removed after the new index
// is in place, so the index never names a missing file.
void remove_stale_levels(const fs::path& dir, const std::set<std::string>& written) {
  static const std::regex level_file("level_-?[0-9]+\\.vtp");
  std::error_code ec;
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (std::regex_match(name, level_file) && !written.count(name)) stale.push_back(it->path());
  }
  for (const fs::path& file : stale) fs::remove(file, ec);
}

}  // namespace

void write_vtp(const fs::path& file, const OutputLevel& level, const VtkWriteOptions& options) {
  // Integer arrays checked as make_polydata converts them: before the file is created.
  const io_detail::LevelCheck check = io_detail::check_output_level(
      level, fmt::format("cannot write {}", subdiv::quoted(file.string())), io_detail::IntegerValues::WhenConverted);
  const auto poly = io_detail::make_polydata(level, options, io_detail::LevelMemory::Share, &check);
  write_file_atomically(file, [&](const fs::path& tmp) {
    io_detail::write_polydata_file(*poly, tmp, file, options);
  });
}

void write_pvd(const fs::path& pvd, std::span<const OutputLevel> levels, const VtkWriteOptions& options) {
  const std::string context = fmt::format("cannot write {}", subdiv::quoted(pvd.string()));
  const std::vector<io_detail::LevelCheck> checks = check_levels(levels, context);
  const fs::path parent = pvd.parent_path().empty() ? fs::path(".") : pvd.parent_path();
  std::error_code ec;
  if (!fs::is_directory(parent, ec))
    throw Error(fmt::format("{}: directory {} does not exist; create it first", context,
                            subdiv::quoted(parent.string())));
  const std::string folder = pvd.stem().string() + "_levels";
  io_detail::require_xml_text(folder, "the levels' folder name", context);  // the index names it
  const fs::path dir = parent / folder;
  const bool created = make_directory(dir, context);
  try {
    StagedFiles staged;  // removes every temporary if anything below throws
    std::vector<Entry> entries;
    std::set<std::string> names;
    // Progress over all files: each weighs as its points and face corners.
    double total = 0, before = 0;
    auto weight = [](const OutputLevel& level) {
      return double(level.mesh->positions.size() + level.mesh->face_vertices.size()) + 1;
    };
    for (const OutputLevel& level : levels) total += weight(level);
    VtkWriteOptions file_options = options;
    for (std::size_t k = 0; k < levels.size(); ++k) {
      const OutputLevel& level = levels[k];
      const std::string name = fmt::format("level_{}.vtp", level.level);
      const fs::path target = dir / name;
      const auto poly = io_detail::make_polydata(level, options, io_detail::LevelMemory::Share, &checks[k]);
      const double share = weight(level) / total;
      if (options.progress)
        file_options.progress = [&, share](double done) { options.progress(before + share * done); };
      io_detail::write_polydata_file(*poly, staged.stage(target), target, file_options);
      before += share;
      entries.push_back({level.level, folder + "/" + name});
      names.insert(name);
    }
    write_collection(staged.stage(pvd), pvd, entries);
    staged.commit();  // level files first, the .pvd last
    remove_stale_levels(dir, names);
  } catch (...) {
    if (created) fs::remove(dir, ec);  // only removes it if still empty
    throw;
  }
}

}  // namespace subdiv
