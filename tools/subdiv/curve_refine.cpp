#include "curve_refine.h"
#include "framework/pipeline/thread_limit.h"
#include "framework/pipeline/memory_guard.h"
#include "framework/pipeline/rational_weights.h"
#include "nonlinear_curve.h"

#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <memory>

#include "framework/io/formats.h"
#include "framework/curve/curve_refine.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"
#include "progress.h"

namespace subdiv::cli {
namespace {

void check_curve_output(const std::filesystem::path& out) {
  const std::string ext = lowercase_extension(out);
  if (ext == ".vtp" || ext == ".pvd" || ext == ".obj") return;
  throw Error(fmt::format("cannot write polylines to '{}': use .vtp or .pvd (ParaView) or .obj ('l' lines); "
                          ".off, .ply and .stl hold no polylines",
                          out.string()));
}

// Point "rule" (the rule that made each point: r >= 0, or -1 - e for end rule e; 0 on
// level 0), "level" and the level's own point arrays (rational weights); cell "polyline" (its number in the input) and "closed".
OutputLevel describe(const CurveLevel& L, const std::vector<std::int8_t>& rules, int l, const MeshData& mesh) {
  OutputLevel out;
  out.mesh = &mesh;
  out.level = l;
  DataArray rule{"rule", 1, std::vector<double>(L.vertex_count, 0.0), true};
  for (size_t v = 0; v < rules.size(); ++v) rule.values[v] = rules[v];
  DataArray level{"level", 1, std::vector<double>(L.vertex_count, double(l)), true};
  DataArray polyline{"polyline", 1, {}, true}, closed{"closed", 1, {}, true};
  for (Index p = 0; p < L.polyline_count(); ++p) {
    polyline.values.push_back(p);
    closed.values.push_back(L.closed[p]);
  }
  out.point_data = {std::move(rule), std::move(level)};
  out.point_data.insert(out.point_data.end(), mesh.point_data.begin(), mesh.point_data.end());  // rational weights
  out.cell_data = {std::move(polyline), std::move(closed)};
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

bool is_curve_scheme(const std::string& scheme) {
  try {
    return scheme_kind(scheme) == "curve";
  } catch (const Error&) {
    return false;
  }
}

// Bytes per point of the finest level: positions of every level, stencil rows, topology.
constexpr double kBytesPerPoint = 160.0;

void check_curve_size(const CurveLevel& base, int arity, int levels) {
  const double points = double(base.vertices.size() + 2 * base.polyline_count()) * std::pow(double(arity), levels);
  if (points > 2.0e9)
    throw Error(fmt::format("{} levels would make about {:.3g} points, more than the 2^31 a level can index; "
                            "ask for fewer levels", levels, points));
  const double need = points * kBytesPerPoint, have = available_memory_bytes();
  if (need > have)
    throw Error(fmt::format("{} levels would make about {:.3g} points and need about {:.1f} GiB, but only "
                            "{:.1f} GiB of memory is available; ask for fewer levels",
                            levels, points, need / (1 << 30), have / (1 << 30)));
}

void refine_curves_command(const CurveRefineRequest& a) {
  const auto t0 = std::chrono::steady_clock::now();
  check_curve_output(a.output);
  const ThreadLimit thread_limit(a.threads, "--threads");
  if (!thread_limit.note().empty()) fmt::print(stderr, "subdiv: note: {}\n", thread_limit.note());
  const auto scheme = load_curve(a.scheme, a.params);
  MeshData mesh = read_mesh(a.mesh);
  // Rational polylines: (w·p, w) refined by the scheme's stencils, projected when written.
  const std::optional<size_t> weights_at = find_rational_weights(mesh.point_data, a.weights, a.mesh);
  if (scheme->nonlinear) {
    if (weights_at)
      throw Error(fmt::format("{}: '{}' is a non-linear curve scheme; rational weights need a linear one (a "
                              "non-linear rule does not commute with projection)",
                              a.mesh, scheme->name));
    return refine_nonlinear_curves(a, *scheme);
  }
  std::vector<double> weights = weights_at ? mesh.point_data[*weights_at].values : std::vector<double>();
  const std::string weights_name = weights_at ? kWeightArrayName : "";  // written as "weight" (OBJ: v x y z w)
  const bool rational = !all_weights_one(weights);  // all 1: the plain refinement, bit for bit
  // A weighted level as written: projected points and the weights as point data (OBJ: v x y z w).
  auto written = [&](const CurveLevel& level, std::vector<double> xyz) {
    if (weights.empty()) return mesh_from_curve_level(level, std::move(xyz));
    if (rational) from_homogeneous(xyz, weights);
    MeshData m = mesh_from_curve_level(level, std::move(xyz));
    m.point_data.push_back({weights_name, 1, weights});
    return m;
  };
  CurveLevel base = curve_level_from_mesh(mesh, a.mesh);
  check_curve_size(base, scheme->arity, a.levels);

  // Level by level, keeping only what the output needs: every level for .pvd, else the
  // finest. Each step's stencil table is dropped once applied.
  Progress progress;
  const std::string ext = lowercase_extension(a.output);
  const bool all_levels = ext == ".pvd";
  std::vector<MeshData> meshes;
  std::vector<CurveLevel> levels_kept;
  std::vector<std::vector<std::int8_t>> rules_kept;
  std::vector<double> positions = mesh.positions;
  if (rational) to_homogeneous(positions, weights);
  if (all_levels || a.levels == 0) {
    meshes.push_back(weights.empty() ? mesh_from_curve_level(base, mesh.positions) : written(base, positions));
    levels_kept.push_back(base);
    rules_kept.emplace_back();
  }
  CurveLevel current = std::move(base);
  for (int l = 0; l < a.levels; ++l) {
    progress.say(fmt::format("level {}/{} of {}", l + 1, a.levels, scheme->name));
    CurveStep step = refine_curve_step(current, evaluate_curve_rules(*scheme, l), scheme->name);
    positions = step.stencils.apply(positions, 3);
    if (!weights.empty()) weights = step.stencils.apply(weights, 1);
    current = std::move(step.child);
    if (all_levels || l + 1 == a.levels) {
      meshes.push_back(written(current, positions));
      levels_kept.push_back(current);
      rules_kept.push_back(std::move(step.origins.rule));
    }
  }
  progress.say(fmt::format("writing {}", a.output));
  if (ext == ".obj") {
    write_mesh(a.output, meshes.back());
  } else {
    std::vector<OutputLevel> out;
    const int first = a.levels + 1 - int(meshes.size());
    for (size_t k = 0; k < meshes.size(); ++k)
      out.push_back(describe(levels_kept[k], rules_kept[k], first + int(k), meshes[k]));
    if (ext == ".vtp") write_vtp(a.output, out.back());
    else write_pvd(a.output, out);
  }
  progress.done();
  if (!a.quiet) {
    const CurveLevel& fine = current;
    int closed = 0;
    for (auto c : fine.closed) closed += c;
    fmt::print("{}: {} level(s) of {} -> {} points on {} polylines ({} closed) in {:.3f} s -> {}\n", a.mesh,
               a.levels, scheme->name, fine.vertex_count, fine.polyline_count(), closed, seconds_since(t0),
               a.output);
  }
}

}  // namespace subdiv::cli
