#include "framework/scheme/scheme_validator.h"

#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "framework/scheme/step_tables.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_loader.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

constexpr double kTolerance = 1e-12;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The line where a rule's text first appears, so editors can jump to it.
int line_of(const std::string& text, const std::string& needle) {
  const size_t at = needle.empty() ? std::string::npos : text.find(needle);
  if (at == std::string::npos) return 0;
  return 1 + int(std::count(text.begin(), text.begin() + at, '\n'));
}

// The number of points a role has around an element of the given sizes; new points count
// as one each because their own rows sum to one.
int role_size(Role role, int n, int k, int n0, int n1) {
  switch (role) {
    case Role::Self: return 1;
    case Role::Ring: case Role::Faces: case Role::Edges: case Role::FaceCentroids: case Role::Diagonals: return n;
    case Role::CreaseNeighbours: case Role::Ends: case Role::Opposite: case Role::Wings: return 2;
    case Role::FarWings: return 4;
    case Role::EndRing0: return n0;
    case Role::EndRing1: return n1;
    case Role::Vertices: return k;
    case Role::Curve: return 0;
    default: break;
  }
  if (const RoleInfo* info = registered_role(role)) return info->max_points(n, k);  // plugin roles
  return 0;
}

struct Sizes {
  int n, k, n0, n1;
};

double weight_at(const CompiledTerm& t, const Sizes& s, int j, Element e) {
  if (e == Element::Edge) return t.weight(2, t.role == Role::Faces ? s.k : 3, j, s.n0, s.n1, s.k, s.k);
  if (e == Element::Face || e == Element::Corner) return t.weight(s.k, s.k, j);
  return t.weight(s.n, s.k, j);
}

double rule_sum(const CompiledRule& rule, const Sizes& s, Element e) {
  double sum = 0;
  for (const auto& t : rule.terms) {
    if (t.role == Role::Curve) {
      for (double w : t.curve_weights) sum += w;
      continue;
    }
    const int count = role_size(t.role, s.n, s.k, s.n0, s.n1);
    for (int j = 0; j < count; ++j) sum += weight_at(t, s, j, e);
  }
  return sum;
}

// Reflection symmetry of a cyclic role: w(j) == w(count - j) (j = 0 is on the axis).
std::string asymmetry(const CompiledRule& rule, const Sizes& s, Element e) {
  for (const auto& t : rule.terms) {
    const bool cyclic = t.role == Role::Ring || t.role == Role::Vertices || t.role == Role::EndRing0 ||
                        t.role == Role::EndRing1 || t.role == Role::Faces || t.role == Role::Edges;
    if (!cyclic) continue;
    if ((t.role == Role::Faces || t.role == Role::Edges) && e == Element::Vertex) continue;  // offset by half a step
    const int count = role_size(t.role, s.n, s.k, s.n0, s.n1);
    const bool from_axis = e == Element::Corner || t.role == Role::EndRing0 || t.role == Role::EndRing1;
    for (int j = 1; j < count; ++j) {
      const int mirror = from_axis ? count - j : (e == Element::Vertex ? (count - j) % count : count - 1 - j);
      const double a = weight_at(t, s, j, e), b = weight_at(t, s, mirror, e);
      if (std::abs(a - b) > kTolerance)
        return fmt::format("role '{}' is not symmetric: w(j={}) = {} but its mirror w(j={}) = {}", role_name(t.role), j,
                           a, mirror, b);
    }
  }
  if (e == Element::Edge && s.n0 == s.n1)
    for (const auto& t : rule.terms)
      if (t.role == Role::Ends && std::abs(weight_at(t, s, 0, e) - weight_at(t, s, 1, e)) > kTolerance)
        return "the two ends get different weights although the edge is symmetric";
  return {};
}

std::vector<Sizes> sizes_to_check(Element e, int lo, int hi, int face_size) {
  std::vector<Sizes> out;
  const int k_lo = face_size ? face_size : 3, k_hi = face_size ? face_size : 8;
  if (e == Element::Vertex)
    for (int n = lo; n <= hi; ++n) out.push_back({n, face_size ? face_size : 4, 0, 0});
  else if (e == Element::Edge)
    for (int a = lo; a <= hi; ++a)
      for (int b = lo; b <= hi; ++b) out.push_back({2, face_size ? face_size : 4, a, b});
  else
    for (int k = k_lo; k <= k_hi; ++k) out.push_back({k, k, 0, 0});
  return out;
}

// Face rules over the corner roles (corners, corner-rings) see each corner's valence and
// boundary flag and the face's counts ex and fe (formula.h), so they are checked over
// configurations of whole triangles: interior ones with every valence triple, and ones with
// one, two or three feature edges, whose corners on those edges lie on a boundary (cb = 1).
bool uses_corner_roles(const CompiledRule& rule) {
  for (const auto& t : rule.terms)
    if (t.role == Role::Corners || t.role == Role::CornerRings) return true;
  return false;
}

struct CornerConfig {
  int n[3];
  int cb[3];
  int fe;
  std::string describe() const {
    return fmt::format("corner valences ({}, {}, {}), on a boundary ({}, {}, {}), fe={}", n[0], n[1], n[2], cb[0], cb[1],
                       cb[2], fe);
  }
};

std::vector<CornerConfig> corner_configs(int lo, int hi) {
  std::vector<CornerConfig> out;
  for (int a = lo; a <= hi; ++a)
    for (int b = lo; b <= hi; ++b)
      for (int c = lo; c <= hi; ++c) out.push_back({{a, b, c}, {0, 0, 0}, 0});
  for (int a = lo; a <= hi; ++a)
    for (int b = lo; b <= hi; ++b) {
      out.push_back({{a, b, b}, {1, 0, 0}, 0});
      for (int cb0 = 0; cb0 < 2; ++cb0) out.push_back({{a, b, b + 1 > hi ? b : b + 1}, {cb0, 1, 1}, 1});
      out.push_back({{2 + (a - lo), b, b}, {1, 1, 1}, 2});
    }
  out.push_back({{2, 2, 2}, {1, 1, 1}, 3});
  return out;
}

double corner_rule_sum(const CompiledRule& rule, const CornerConfig& c, std::string& asymmetric) {
  int ex = 0;
  for (int i = 0; i < 3; ++i) ex += c.cb[i] == 0 && c.n[i] != 6;
  double sum = 0;
  for (const auto& t : rule.terms) {
    for (int i = 0; i < 3; ++i) {
      if (t.role == Role::Corners) sum += t.corner_weight(c.n[i], 3, i, i, c.cb[i], ex, c.fe);
      if (t.role != Role::CornerRings) continue;
      for (int j = 0; j < c.n[i]; ++j) {
        const double w = t.corner_weight(c.n[i], 3, j, i, c.cb[i], ex, c.fe);
        const double mirror = t.corner_weight(c.n[i], 3, c.n[i] - 1 - j, i, c.cb[i], ex, c.fe);
        // The face is symmetric about a corner when fe = 0, and about corner 0 when fe = 1.
        if ((c.fe == 0 || (c.fe == 1 && i == 0)) && asymmetric.empty() && std::abs(w - mirror) > kTolerance)
          asymmetric = fmt::format("role 'corner-rings' is not symmetric: at corner {} w(j={}) = {} but its mirror "
                                   "w(j={}) = {}", i, j, w, c.n[i] - 1 - j, mirror);
        sum += w;
      }
    }
    if (t.role == Role::Vertices || t.role == Role::Edges)
      for (int j = 0; j < 3; ++j) sum += t.corner_weight(3, 3, j, 0, 0, ex, c.fe);
  }
  return sum;
}

void check_corner_rule(const CompiledRule& rule, const std::string& where, int lo, int hi, ValidationReport& report) {
  for (const CornerConfig& c : corner_configs(lo, hi)) {
    ++report.checks;
    std::string asymmetric;
    const double sum = corner_rule_sum(rule, c, asymmetric);
    if (!std::isfinite(sum) || std::abs(sum - 1) > 1e-9) {
      report.errors.push_back(
          {fmt::format("{}: weights sum to {} at {}, not 1 (every rule must be affine)", where, sum, c.describe())});
      return;
    }
    if (!asymmetric.empty()) {
      report.errors.push_back({fmt::format("{}: {} at {}", where, asymmetric, c.describe())});
      return;
    }
  }
}

int natural_face_size(const Scheme& s) {
  if (s.required_face_size) return s.required_face_size;
  return splitter_info(s.split()).required_face_size;
}

void check_step(const Scheme& scheme, const StepRules& step, const std::string& text, int lo, int hi,
                ValidationReport& report) {
  const WeightTables tables = step_weight_tables(scheme, step, hi, 8, 0);
  const int face_size = natural_face_size(scheme);
  for (int e = 0; e < kElementCount; ++e)
    for (int c = 0; c < kContextCount; ++c) {
      if (!step.rules[e][c]) continue;  // engine defaults are affine by construction
      const CompiledRule& rule = tables.rules[e][c];
      const Rule& source = *step.rules[e][c];
      const std::string where = fmt::format("{}:{}: {} ({})", scheme.path,
                                            line_of(text, source.terms.empty() ? "" : source.terms[0].weight),
                                            source.where.substr(source.where.find(": ") + 2), context_name(Context(c)));
      if (Element(e) == Element::Face && uses_corner_roles(rule)) {
        check_corner_rule(rule, where, lo, hi, report);
        continue;
      }
      bool reported = false;
      for (const Sizes& s : sizes_to_check(Element(e), lo, hi, face_size)) {
        ++report.checks;
        if (reported) continue;
        const double sum = rule_sum(rule, s, Element(e));
        const std::string at = Element(e) == Element::Edge ? fmt::format("n0={}, n1={}", s.n0, s.n1)
                               : Element(e) == Element::Vertex ? fmt::format("n={}", s.n)
                                                               : fmt::format("k={}", s.k);
        if (!std::isfinite(sum) || std::abs(sum - 1) > 1e-9) {
          report.errors.push_back({fmt::format("{}: weights sum to {} at {}, not 1 (every rule must be affine)", where, sum, at)});
          reported = true;
        } else if (std::string why = asymmetry(rule, s, Element(e)); !why.empty()) {
          report.errors.push_back({fmt::format("{}: {} at {}", where, why, at)});
          reported = true;
        }
      }
    }
}

}  // namespace

ValidationReport validate_scheme_file(const std::string& name_or_path, int lo, int hi) {
  if (lo < kMinCheckedValence || hi > kMaxCheckedValence || lo > hi)
    throw Error(fmt::format("valences {}..{} cannot be checked: give {} <= --min-valence <= --max-valence <= {}", lo,
                            hi, kMinCheckedValence, kMaxCheckedValence));
  ValidationReport report;
  try {
    const std::string path = scheme_file_path(name_or_path);
    report.kind = scheme_file_kind(path);
    if (report.kind == "curve") {
      const auto curve = load_curve_scheme(path, {});
      report.scheme_name = curve->name;
      // Each rule of a curve scheme must be affine too.
      FormulaSet formulas(curve->parameters, curve->definitions);
      for (size_t r = 0; r < curve->weights.size(); ++r) {
        double sum = 0;
        for (size_t t = 0; t < curve->weights[r].size(); ++t)
          sum += formulas.evaluate(formulas.add(curve->weights[r][t], path), {0, 0, double(t)});
        ++report.checks;
        if (std::abs(sum - 1) > 1e-9)
          report.errors.push_back({fmt::format("{}:{}: rules[{}]: weights sum to {}, not 1", path,
                                               line_of(read_text(path), curve->weights[r][0]), r, sum)});
      }
      return report;
    }
    const auto scheme = load_scheme(path);
    report.scheme_name = scheme->name;
    const std::string text = read_text(path);
    for (const auto& step : scheme->steps) check_step(*scheme, step, text, lo, hi, report);
  } catch (const Error& e) {
    report.errors.push_back({e.what()});
  }
  return report;
}

}  // namespace subdiv
