#include "curve_refine.h"

#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <fstream>

#include "framework/curve/curve_refine.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "framework/io/vtk_output.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"
#include "progress.h"

namespace subdiv::cli {
namespace {

std::string extension_of(const std::filesystem::path& p) {
  std::string ext = p.extension().string();
  for (char& c : ext) c = char(std::tolower(c));
  return ext;
}

void check_curve_output(const std::filesystem::path& out) {
  const std::string ext = extension_of(out);
  if (ext == ".vtp" || ext == ".pvd" || ext == ".obj") return;
  throw Error(fmt::format("cannot write polylines to '{}': use .vtp or .pvd (ParaView) or .obj ('l' lines); "
                          ".off, .ply and .stl hold no polylines",
                          out.string()));
}

// Bytes per point of the finest level: positions of every level, stencil rows, topology.
constexpr double kBytesPerPoint = 160.0;

double available_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kb = 0;
  while (meminfo >> key >> kb) {
    if (key == "MemAvailable:") return kb * 1024.0;
    meminfo.ignore(256, '\n');
  }
  return 1e18;
}

void check_curve_size(const CurveLevel& base, int arity, int levels) {
  const double points = double(base.vertices.size() + 2 * base.polyline_count()) * std::pow(double(arity), levels);
  if (points > 2.0e9)
    throw Error(fmt::format("{} levels would make about {:.3g} points, more than the 2^31 a level can index; "
                            "ask for fewer levels", levels, points));
  const double need = points * kBytesPerPoint, have = available_bytes();
  if (need > have)
    throw Error(fmt::format("{} levels would make about {:.3g} points and need about {:.1f} GiB, but only "
                            "{:.1f} GiB of memory is available; ask for fewer levels",
                            levels, points, need / (1 << 30), have / (1 << 30)));
}

OutputLevel describe(const CurveHierarchy& h, int l, const MeshData& mesh) {
  const CurveLevel& L = h.levels[l];
  OutputLevel out;
  out.mesh = &mesh;
  out.level = l;
  DataArray rule{"rule", 1, std::vector<double>(L.vertex_count, 0.0), true};
  if (l > 0)
    for (Index v = 0; v < L.vertex_count; ++v) rule.values[v] = h.origins[l - 1].rule[v];
  DataArray level{"level", 1, std::vector<double>(L.vertex_count, double(l)), true};
  DataArray polyline{"polyline", 1, {}, true}, closed{"closed", 1, {}, true};
  for (Index p = 0; p < L.polyline_count(); ++p) {
    polyline.values.push_back(p);
    closed.values.push_back(L.closed[p]);
  }
  out.point_data = {std::move(rule), std::move(level)};
  out.cell_data = {std::move(polyline), std::move(closed)};
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

bool is_curve_scheme(const std::string& scheme) { return scheme_kind(scheme) == "curve"; }

void refine_curves_command(const CurveRefineRequest& a) {
  const auto t0 = std::chrono::steady_clock::now();
  check_curve_output(a.output);
  const auto scheme = load_curve(a.scheme, a.params);
  const MeshData mesh = read_mesh(a.mesh);
  CurveLevel base = curve_level_from_mesh(mesh, a.mesh);
  check_curve_size(base, scheme->arity, a.levels);

  Progress progress;
  progress.say(fmt::format("refining polylines: {} levels of {}", a.levels, scheme->name));
  const CurveHierarchy h = refine_curves(*scheme, std::move(base), a.levels);
  std::vector<MeshData> meshes;
  std::vector<double> positions = mesh.positions;
  for (int l = 0; l <= a.levels; ++l) {
    if (l > 0) positions = h.stencils[l - 1].apply(positions, 3);
    meshes.push_back(mesh_from_curve_level(h.levels[l], positions));
  }
  progress.say(fmt::format("writing {}", a.output));
  const std::string ext = extension_of(a.output);
  if (ext == ".obj") {
    write_mesh(a.output, meshes.back());
  } else {
    std::vector<OutputLevel> levels;
    for (int l = 0; l <= a.levels; ++l) levels.push_back(describe(h, l, meshes[l]));
    if (ext == ".vtp") write_vtp(a.output, levels.back());
    else write_pvd(a.output, levels);
  }
  progress.done();
  if (!a.quiet) {
    const CurveLevel& fine = h.levels.back();
    int closed = 0;
    for (auto c : fine.closed) closed += c;
    fmt::print("{}: {} level(s) of {} -> {} points on {} polylines ({} closed) in {:.3f} s -> {}\n", a.mesh,
               a.levels, scheme->name, fine.vertex_count, fine.polyline_count(), closed, seconds_since(t0),
               a.output);
  }
}

}  // namespace subdiv::cli
