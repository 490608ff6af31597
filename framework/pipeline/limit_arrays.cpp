#include "framework/pipeline/limit_arrays.h"

#include "framework/analysis/surface/rim_rules.h"
#include "framework/limit/corner_limit.h"
#include "framework/pipeline/rational_weights.h"
#include "framework/util/option_spelling.h"

namespace subdiv {
namespace {

const DataArray* named(const std::vector<DataArray>& arrays, const std::string& name) {
  for (const DataArray& a : arrays)
    if (a.name == name) return &a;
  return nullptr;
}

}  // namespace

LimitArrays limit_arrays(const SchemeSequence& seq, const Hierarchy& h, const RefineOptions& options,
                         LevelData& finest, bool move_to_limit, const std::string& mesh_name,
                         const std::string& weights) {
  LimitOptions lo;
  lo.features = options.features;
  lo.first_step = options.first_step + seq.total_levels;
  const Level& level = h.levels.back();
  std::shared_ptr<const Scheme> with_rim;  // a scheme without boundary rules on a closed mesh
  const Scheme& scheme = scheme_for_cut_rims(*seq.schemes.back(), level, with_rim);
  SchemeLimits limits(scheme, lo);
  LimitArrays out;
  const std::string not_c1_why = limits.regular_not_c1();
  if (!not_c1_why.empty() && !move_to_limit)
    throw OptionError((mesh_name.empty() ? "" : mesh_name + ": ") + not_c1(scheme, "at a regular vertex " + not_c1_why) +
                      "; leave out {normals} ({limit} alone moves the points to their limits)");
  if (const DataArray* w = weights.empty() ? nullptr : named(finest.point_data, weights)) {
    std::vector<double> homogeneous = finest.positions;
    to_homogeneous(homogeneous, w->values);
    out.result = limits.evaluate(level, homogeneous, w->values);
  } else {
    out.result = limits.evaluate(level, finest.positions);
  }
  const LimitResult& limit = out.result;
  if (move_to_limit) {
    finest.positions = limit.positions;
    bool data = false;
    for (const DataArray& d : finest.point_data) data = data || !d.integer;
    if (data) {
      const StencilTable masks = limits.stencils(level).position;
      for (DataArray& d : finest.point_data)
        if (!d.integer) d.values = masks.apply(d.values, d.components);
    }
  }
  if (!not_c1_why.empty()) {
    out.warnings.push_back(not_c1(scheme, "at a regular vertex " + not_c1_why) +
                           "; the points are on the limit, the point data 'normal' and 'normal_exact' are left out");
    out.point_data.push_back(
        DataArray{"limit_exact", 1, std::vector<double>(limit.exact.begin(), limit.exact.end()), true});
    return out;
  }
  out.point_data.push_back(DataArray{"normal", 3, limit.normals, false, ArrayRole::Normals});
  out.point_data.push_back(
      DataArray{"limit_exact", 1, std::vector<double>(limit.exact.begin(), limit.exact.end()), true});
  out.point_data.push_back(
      DataArray{"normal_exact", 1, std::vector<double>(limit.normal_exact.begin(), limit.normal_exact.end()), true});
  return out;
}

}  // namespace subdiv
