#include "framework/pipeline/curve_pipeline.h"

#include <cmath>
#include <fmt/format.h>
#include <optional>

#include "framework/curve/curve_refine.h"
#include "framework/io/mesh_read.h"
#include "framework/pipeline/memory_guard.h"
#include "framework/pipeline/rational_weights.h"
#include "framework/plugin/polyline_refine.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "framework/util/byte_size_text.h"
#include "framework/util/memory_limit.h"
#include "framework/util/option_spelling.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

// Bytes per point of the finest level: positions of every level, stencil rows, topology.
constexpr double kBytesPerPoint = 160.0;

void say(const CurveRefineRequest& r, const std::string& phase) {
  if (r.progress) r.progress(phase);
}

std::shared_ptr<const CurveScheme> load_request_curve(const CurveRefineRequest& r) {
  if (r.scheme.is_json_text) return load_curve_text(r.scheme.text, r.scheme.label, r.scheme.parameters);
  return load_curve(r.scheme.text, r.scheme.parameters);
}

MeshData request_mesh(CurveRefineRequest& r) {
  if (r.mesh_file.empty()) return std::move(r.mesh);
  if (r.mesh_name.empty()) r.mesh_name = r.mesh_file;
  return read_mesh(r.mesh_file);
}

// Cell arrays are per face, and polylines have none: they are not carried (and said so).
// The description's own cell arrays (describe_curve_level) are made anew without a note.
std::vector<std::string> drop_cell_data(MeshData& mesh) {
  std::vector<std::string> notes;
  for (const auto& a : mesh.cell_data)
    if (a.name != "polyline" && a.name != "closed") notes.push_back(fmt::format("cell array {} is not carried: polylines carry point data only", subdiv::quoted(a.name)));
  mesh.cell_data.clear();
  return notes;
}

// ---- linear schemes: one stencil table a level, applied to positions and every array ------

// The point arrays as the level's values; polylines have no element origins to take labels
// by, so integer arrays are interpolated like the others.
struct CurveValues {
  std::vector<double> positions;  // homogeneous (w·p) when rational
  std::vector<DataArray> point_data;
  std::optional<size_t> weights_at;
  bool rational = false;

  MeshData mesh(const CurveLevel& level) const {
    std::vector<double> xyz = positions;
    if (rational) from_homogeneous(xyz, point_data[*weights_at].values);
    MeshData m = mesh_from_curve_level(level, std::move(xyz));
    m.point_data = point_data;
    return m;
  }
};

// The refined weights are written as "weight" (OBJ: the fourth coordinate), whatever the
// input called them, unless another array has that name (as refine_pipeline.cpp does).
void rename_weights(std::vector<DataArray>& point_data, size_t weights_at) {
  for (const DataArray& a : point_data)
    if (a.name == kWeightArrayName) return;
  point_data[weights_at].name = kWeightArrayName;
}

CurveValues base_values(MeshData& mesh, const CurveRefineRequest& r) {
  CurveValues v;
  v.point_data = std::move(mesh.point_data);
  for (auto& a : v.point_data) a.integer = false;
  v.weights_at = find_rational_weights(v.point_data, r.weights_array, r.mesh_name);
  v.rational = v.weights_at && !all_weights_one(v.point_data[*v.weights_at].values);  // all 1: the plain path
  if (v.weights_at) rename_weights(v.point_data, *v.weights_at);
  v.positions = std::move(mesh.positions);
  if (v.rational) to_homogeneous(v.positions, v.point_data[*v.weights_at].values);
  return v;
}

void refine_linear(const CurveScheme& scheme, MeshData mesh, const CurveRefineRequest& r, CurveRefineResult& out) {
  CurveLevel current = curve_level_from_mesh(mesh, r.mesh_name);
  check_curve_size(current, scheme.arity, r.levels, r.memory_budget);
  CurveValues values = base_values(mesh, r);
  auto keep = [&](int level, const CurveLevel& topology, std::vector<std::int8_t> rules) {
    out.levels.push_back({level, topology, values.mesh(topology), std::move(rules)});
  };
  if (r.keep_all_levels || r.levels == 0)
    keep(0, current, std::vector<std::int8_t>(size_t(current.vertex_count), 0));
  for (int l = 0; l < r.levels; ++l) {
    say(r, fmt::format("level {}/{} of {}", l + 1, r.levels, scheme.name));
    // Each step's stencil table is dropped once applied.
    CurveStep step = refine_curve_step(current, evaluate_curve_rules(scheme, l), scheme.name);
    values.positions = step.stencils.apply(values.positions, 3);
    for (auto& a : values.point_data) a.values = step.stencils.apply(a.values, a.components);
    current = std::move(step.child);
    if (r.keep_all_levels || l + 1 == r.levels) keep(l + 1, current, std::move(step.origins.rule));
  }
}

// ---- non-linear schemes (plugins): each polyline mapped by the scheme's own function -------

// Every polyline of `level` as its own run of points (xyz), so each can be refined alone.
std::vector<std::vector<double>> polyline_points(const CurveLevel& level, const std::vector<double>& positions) {
  std::vector<std::vector<double>> out(level.polyline_count());
  for (Index p = 0; p < level.polyline_count(); ++p)
    for (Index v : level.polyline(p))
      out[p].insert(out[p].end(), positions.begin() + 3 * v, positions.begin() + 3 * v + 3);
  return out;
}

// The polylines as a level of their own: no point is shared between two polylines.
RefinedCurveLevel level_of(int level, const std::vector<std::vector<double>>& polylines,
                           const std::vector<std::uint8_t>& closed) {
  RefinedCurveLevel out;
  out.level = level;
  CurveLevel& t = out.topology;
  std::vector<double> positions;
  for (size_t p = 0; p < polylines.size(); ++p) {
    positions.insert(positions.end(), polylines[p].begin(), polylines[p].end());
    for (size_t i = 0; i < polylines[p].size() / 3; ++i) t.vertices.push_back(t.vertex_count++);
    t.offsets.push_back(Index(t.vertices.size()));
  }
  t.closed = closed;
  out.mesh = mesh_from_curve_level(t, std::move(positions));
  return out;
}

void refine_nonlinear(const CurveScheme& scheme, MeshData mesh, const CurveRefineRequest& r, CurveRefineResult& out) {
  if (find_rational_weights(mesh.point_data, r.weights_array, r.mesh_name))
    throw Error(fmt::format("{}: {} is a non-linear curve scheme; rational weights need a linear one (a "
                            "non-linear rule does not commute with projection)",
                            r.mesh_name, subdiv::quoted(scheme.name)));
  for (const auto& a : mesh.point_data)
    out.notes.push_back(fmt::format("point array {} is not carried: non-linear scheme {} has no rule to carry "
                                    "point data by", subdiv::quoted(a.name), subdiv::quoted(scheme.name)));
  const CurveLevel base = curve_level_from_mesh(mesh, r.mesh_name);
  check_curve_size(base, scheme.arity, r.levels, r.memory_budget);
  std::vector<std::vector<double>> polylines = polyline_points(base, mesh.positions);
  if (r.keep_all_levels || r.levels == 0) out.levels.push_back(level_of(0, polylines, base.closed));
  for (int l = 0; l < r.levels; ++l) {
    say(r, fmt::format("level {}/{} of {} (non-linear)", l + 1, r.levels, scheme.name));
    for (Index p = 0; p < Index(polylines.size()); ++p)
      polylines[p] = refine_polyline(scheme, polylines[p], 3, base.is_closed(p), 1, l);
    if (r.keep_all_levels || l + 1 == r.levels) out.levels.push_back(level_of(l + 1, polylines, base.closed));
  }
}

}  // namespace

void check_curve_size(const CurveLevel& base, int arity, int levels, double budget) {
  const double points = double(base.vertices.size() + 2 * size_t(base.polyline_count())) *
                        std::pow(double(arity), levels);
  if (points > 2.0e9)
    throw OptionError(fmt::format("{} levels would make about {:.3g} points, more than the 2^31 a level can "
                                  "index; ask for fewer levels ({{levels}})",
                                  levels, points));
  const double need = points * kBytesPerPoint;
  const MemoryBudget have = memory_budget(budget);
  if (need > have.bytes) {
    const auto [need_text, have_text] = byte_sizes_compared(need, have.bytes);
    throw OptionError(fmt::format("{} levels would make about {:.3g} points and need about {}, but only {} of memory "
                                  "is available (limited by {}); ask for fewer levels ({{levels}})",
                                  levels, points, need_text, have_text, have.source));
  }
}

CurveRefineResult refine_curve_request(CurveRefineRequest request) {
  if (request.levels < 0)
    throw OptionError(fmt::format("{{levels}} {}: give 0 or more levels", request.levels));
  CurveRefineResult out;
  out.scheme = load_request_curve(request);
  MeshData mesh = request_mesh(request);
  out.notes = drop_cell_data(mesh);
  if (out.scheme->nonlinear) refine_nonlinear(*out.scheme, std::move(mesh), request, out);
  else refine_linear(*out.scheme, std::move(mesh), request, out);
  return out;
}

CurveLevelDescription describe_curve_level(const RefinedCurveLevel& level) {
  CurveLevelDescription d;
  // A user array with one of these names is kept instead (as level_description.h does).
  auto add_unless_named = [&](DataArray a) {
    for (const DataArray& user : level.mesh.point_data)
      if (user.name == a.name) return;
    d.point_data.push_back(std::move(a));
  };
  const size_t points = size_t(level.topology.vertex_count);
  if (!level.rules.empty()) {
    DataArray rule{"rule", 1, std::vector<double>(points, 0.0), true};
    for (size_t v = 0; v < level.rules.size() && v < points; ++v) rule.values[v] = level.rules[v];
    add_unless_named(std::move(rule));
  }
  add_unless_named({"level", 1, std::vector<double>(points, double(level.level)), true});
  DataArray polyline{"polyline", 1, {}, true}, closed{"closed", 1, {}, true};
  for (Index p = 0; p < level.topology.polyline_count(); ++p) {
    polyline.values.push_back(p);
    closed.values.push_back(level.topology.closed[p]);
  }
  d.cell_data = {std::move(polyline), std::move(closed)};
  return d;
}

}  // namespace subdiv
