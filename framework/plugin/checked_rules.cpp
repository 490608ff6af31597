#include "framework/plugin/checked_rules.h"

#include <cmath>
#include <exception>
#include <utility>

#include <fmt/format.h>

#include "framework/rules/row_builder.h"
#include "framework/util/error.h"

namespace subdiv {

void rethrow_plugin_exception(const std::string& who, const char* what) {
  try {
    throw;
  } catch (const Error& e) {
    throw Error(fmt::format("{}: {}: {}", who, what, e.what()));
  } catch (const std::exception& e) {
    throw Error(fmt::format("{}: {} threw an exception: {}", who, what, e.what()));
  } catch (...) {
    throw Error(fmt::format("{}: {} threw something that is not a std::exception; fix the plugin", who, what));
  }
}

namespace {

// The row a plugin writes goes into a builder of this thread first, to be checked; a rule
// that (unusually) runs another rule while it writes gets a builder of its own.
struct Scratch {
  RowBuilder builder;
  bool busy = false;
};

class CheckedRow {
public:
  CheckedRow() : scratch_(scratch()), own_(scratch_.busy ? std::make_unique<RowBuilder>() : nullptr) {
    if (!own_) scratch_.busy = true;
    builder().clear();
  }
  ~CheckedRow() {
    if (!own_) scratch_.busy = false;
  }
  RowBuilder& builder() { return own_ ? *own_ : scratch_.builder; }

  // Every index within the parent level and every weight finite, then the row to `row`.
  void pass_on(const CodeRuleInput& in, RowWriter& row, const std::string& who, const char* what, Index element) {
    const auto& indices = builder().indices();
    const auto& weights = builder().weights();
    for (std::size_t i = 0; i < indices.size(); ++i) {
      if (indices[i] < 0 || indices[i] >= in.parent.vertex_count)
        throw Error(fmt::format("{}: its {} rule for {} {} (level {}) adds parent vertex {}, but the level has {} "
                                "vertices (0 to {}); fix the plugin",
                                who, what, what, element, in.level, indices[i], in.parent.vertex_count,
                                in.parent.vertex_count - 1));
      if (!std::isfinite(weights[i]))
        throw Error(fmt::format("{}: its {} rule for {} {} (level {}) gives parent vertex {} the weight {}; weights "
                                "must be finite",
                                who, what, what, element, in.level, indices[i], weights[i]));
    }
    for (std::size_t i = 0; i < indices.size(); ++i) row.add(indices[i], weights[i]);
  }

private:
  static Scratch& scratch() {
    thread_local Scratch s;
    return s;
  }
  Scratch& scratch_;
  std::unique_ptr<RowBuilder> own_;
};

// Runs `call(writer)` on a checked row and passes the row on.
template <typename Call>
void checked_row(const CodeRuleInput& in, RowWriter& row, const std::string& who, const char* what, Index element,
                 Call&& call) {
  CheckedRow checked;
  RowWriter writer(checked.builder(), 1.0);
  try {
    call(writer);
  } catch (...) {
    rethrow_plugin_exception(who, fmt::format("its {} rule for {} {}", what, what, element).c_str());
  }
  checked.pass_on(in, row, who, what, element);
}

}  // namespace

CodeRules checked_code_rules(CodeRules rules, std::string who) {
  CodeRules out;
  out.handles_features = rules.handles_features;
  if (auto f = std::move(rules.vertex))
    out.vertex = [f, who](const CodeRuleInput& in, Index v, Context c, RowWriter& row) {
      checked_row(in, row, who, "vertex", v, [&](RowWriter& w) { f(in, v, c, w); });
    };
  if (auto f = std::move(rules.edge))
    out.edge = [f, who](const CodeRuleInput& in, Index e, int local, Context c, RowWriter& row) {
      checked_row(in, row, who, "edge", e, [&](RowWriter& w) { f(in, e, local, c, w); });
    };
  if (auto f = std::move(rules.face))
    out.face = [f, who](const CodeRuleInput& in, Index face, RowWriter& row) {
      checked_row(in, row, who, "face", face, [&](RowWriter& w) { f(in, face, w); });
    };
  if (auto f = std::move(rules.corner))
    out.corner = [f, who](const CodeRuleInput& in, Index face, int corner, Context c, RowWriter& row) {
      checked_row(in, row, who, "corner", face, [&](RowWriter& w) { f(in, face, corner, c, w); });
    };
  return out;
}

NonlinearRule checked_nonlinear_rule(NonlinearRule rule, std::string who) {
  if (!rule) return rule;
  return [rule, who](const NonlinearStepInput& in, std::span<const double> parent, std::span<double> child,
                     int channels) {
    call_plugin(who, "its non-linear rule", [&] { rule(in, parent, child, channels); });
    for (std::size_t i = 0; i < child.size(); ++i)
      if (!std::isfinite(child[i]))
        throw Error(fmt::format("{}: its non-linear rule gives child vertex {} the value {} (level {}); values must "
                                "be finite",
                                who, channels > 0 ? i / std::size_t(channels) : i, child[i], in.level));
  };
}

PolylineRule checked_polyline_rule(PolylineRule rule, std::string who) {
  if (!rule) return rule;
  return [rule, who](std::span<const double> points, int dim, bool closed, int level) {
    std::vector<double> out = call_plugin(who, "its non-linear curve rule", [&] { return rule(points, dim, closed, level); });
    for (std::size_t i = 0; i < out.size(); ++i)
      if (!std::isfinite(out[i]))
        throw Error(fmt::format("{}: its non-linear curve rule gives the value {} (level {}); values must be finite",
                                who, out[i], level));
    return out;
  };
}

}  // namespace subdiv
