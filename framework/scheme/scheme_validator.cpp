#include "framework/scheme/scheme_validator.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <functional>
#include <sstream>

#include "framework/scheme/step_tables.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_loader.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "framework/util/json_path_line.h"
#include "framework/util/option_spelling.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

constexpr double kTolerance = 1e-12;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The line where a formula's text first appears, so editors can jump to it (curve rules,
// which carry no place of their own).
int line_of(const std::string& text, const std::string& needle) {
  const size_t at = needle.empty() ? std::string::npos : text.find(needle);
  if (at == std::string::npos) return 0;
  return 1 + int(std::count(text.begin(), text.begin() + at, '\n'));
}

// A rule's or term's place, "FILE: rules.face[0]", as "FILE:LINE: rules.face[0]": the line of
// its JSON path, not of the first text equal to its formula (which may be another rule's, or
// none when the rule has no terms). Unchanged where the text has no such path (a plugin's scheme).
std::string placed(const std::string& where, const std::string& file, const std::string& text) {
  const std::string with_line = with_json_line(where + ": ", file, text);
  return with_line.substr(0, with_line.size() - 2);
}

// The number of points a role has around an element of the given sizes; new points count
// as one each because their own rows sum to one.
int role_size(Role role, int n, int k, int n0, int n1) {
  switch (role) {
    case Role::Self: case Role::CreasePoint: return 1;
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
        return fmt::format("role {} is not symmetric: w(j={}) = {} but its mirror w(j={}) = {}", subdiv::quoted(role_name(t.role)), j,
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

// The refusal of a rule whose weights at `at` do not sum to 1. A sum that is not a number
// or infinite comes from a formula outside its domain at that size, which reads nothing
// like a wrong weight ("sum to -nan") to the scheme's author: said as such, with the fix.
std::string not_affine(const std::string& where, double sum, const std::string& at, const std::string& at_parameters) {
  if (!std::isfinite(sum))
    return fmt::format("{}: the weights at {}{} are not finite numbers (they sum to {}): a formula divides by zero or "
                       "leaves its domain there (sqrt or log of a negative number, acos beyond 1); guard that case "
                       "in the formula (for example n == 6 ? a : b){}",
                       where, at, at_parameters, std::isnan(sum) ? std::string("NaN") : fmt::format("{}", sum),
                       at_parameters.empty() ? "" : ", or leave the parameter's value out of its range (\"min_exclusive\", "
                                                    "\"max_exclusive\")");
  return fmt::format("{}: weights sum to {} at {}{}, not 1 (every rule must be affine)", where, sum, at,
                     at_parameters);
}

void check_corner_rule(const CompiledRule& rule, const std::string& where, int lo, int hi, ValidationReport& report,
                       const std::string& at_parameters) {
  for (const CornerConfig& c : corner_configs(lo, hi)) {
    ++report.checks;
    std::string asymmetric;
    const double sum = corner_rule_sum(rule, c, asymmetric);
    if (!std::isfinite(sum) || std::abs(sum - 1) > 1e-9) {
      report.errors.push_back(
          {not_affine(where, sum, c.describe(), at_parameters)});
      return;
    }
    if (!asymmetric.empty()) {
      report.errors.push_back({fmt::format("{}: {} at {}{}", where, asymmetric, c.describe(), at_parameters)});
      return;
    }
  }
}

int natural_face_size(const Scheme& s) {
  if (s.required_face_size) return s.required_face_size;
  return splitter_info(s.split()).required_face_size;
}

// The faces a split makes: 3 triangles, 4 quads, 0 any polygon, -1 not known (a plugin's).
int split_output_faces(SplitKind split) {
  switch (split) {
    case SplitKind::Quad: return 4;
    case SplitKind::Triangle:
    case SplitKind::Sqrt3: return 3;
    case SplitKind::Dual:
    case SplitKind::MidEdge: return 0;
  }
  return -1;
}

std::string faces_name(int size) { return size == 3 ? "triangles" : size == 4 ? "quads" : "any polygons"; }

// Roles that exist only around faces of one size (element_rules.cpp refuses others when a
// mesh is refined): the triangle roles of edge rules and the quads' diagonals.
int role_face_size(Role role) {
  if (role == Role::Opposite || role == Role::Wings || role == Role::FarWings) return 3;
  if (role == Role::Diagonals) return 4;
  return 0;
}

// A role is meaningful for a step when every level the step's rules run on has the faces it
// needs: a split's rules see the base mesh (the scheme's "faces") and then the split's own
// output; a smoothing pass sees the output of the scheme's split.
void check_roles(const Scheme& scheme, const StepRules& step, const std::string& text, ValidationReport& report) {
  const int made = split_output_faces(scheme.split());
  if (made < 0) return;  // a plugin's split: its faces are not known
  const int base = natural_face_size(scheme);
  for (int e = 0; e < kElementCount; ++e)
    for (int c = 0; c < kContextCount; ++c) {
      if (!step.rules[e][c]) continue;
      for (const Term& t : step.rules[e][c]->terms) {
        const int needs = role_face_size(t.role);
        if (!needs) continue;
        std::string why;
        if (made != needs)
          why = fmt::format("the {} split makes {}", splitter_info(scheme.split()).name, faces_name(made));
        else if (step.is_split && base != needs)
          why = fmt::format("the base mesh may have {} (the scheme's \"faces\" is not \"{}\")", faces_name(base),
                            escaped(faces_name(needs)));
        if (why.empty()) continue;
        ++report.checks;
        report.errors.push_back({fmt::format("{} ({}): role {} needs {}, but {}", placed(t.where, scheme.path, text),
                                             context_name(Context(c)), subdiv::quoted(role_name(t.role)), faces_name(needs), why)});
      }
    }
}

// Edge rules that read their ends' sectors (b0, b1, m0, m1, e0, e1; the end-sector roles) are
// also checked with one or both ends on a boundary: a boundary end of valence m + 1 whose one
// sector of m faces holds the edge at e = 1 .. m - 1, the other end inside (valence lo .. hi)
// or on a boundary too.
struct SectorEnd {
  int n, b, m, e;
};

double sector_rule_sum(const CompiledRule& rule, const SectorEnd& a, const SectorEnd& b) {
  SectorVariables sv;
  sv.b[0] = a.b, sv.m[0] = a.m, sv.e[0] = a.e, sv.b[1] = b.b, sv.m[1] = b.m, sv.e[1] = b.e;
  double sum = 0;
  for (const auto& t : rule.terms) {
    if (t.role == Role::Curve) continue;  // smooth rules only
    int count = role_size(t.role, 2, 3, a.n, b.n);
    if (t.role == Role::EndSector0) count = a.b ? a.m + 1 : 0;
    if (t.role == Role::EndSector1) count = b.b ? b.m + 1 : 0;
    for (int j = 0; j < count; ++j) sum += t.edge_weight(3, j, a.n, b.n, 3, 3, sv);
  }
  return sum;
}

void check_sector_rule(const CompiledRule& rule, const std::string& where, int lo, int hi, ValidationReport& report,
                       const std::string& at_parameters) {
  std::vector<SectorEnd> boundary, inside;
  for (int m = 2; m + 1 <= hi; ++m)
    for (int e = 1; e < m; ++e) boundary.push_back({m + 1, 1, m, e});
  for (int n = lo; n <= hi; ++n) inside.push_back({n, 0, 0, 0});
  auto describe = [](const SectorEnd& x) {
    return x.b ? fmt::format("boundary valence {} (sector of {} faces, edge {})", x.n, x.m, x.e)
               : fmt::format("interior valence {}", x.n);
  };
  for (const SectorEnd& a : boundary)
    for (const auto* others : {&inside, &boundary})
      for (const SectorEnd& b : *others)
        for (int flip = 0; flip < 2; ++flip) {
          ++report.checks;
          const SectorEnd& end0 = flip ? b : a;
          const SectorEnd& end1 = flip ? a : b;
          const double sum = sector_rule_sum(rule, end0, end1);
          if (!std::isfinite(sum) || std::abs(sum - 1) > 1e-9) {
            report.errors.push_back({not_affine(where, sum, fmt::format("end 0 {}, end 1 {}", describe(end0), describe(end1)),
                                                at_parameters)});
            return;
          }
        }
}

// Crease-end rules are one-sided by nature (they lean towards the corner), so only their
// weight sums are checked, at every valence.
void check_crease_ends(const Scheme& scheme, const StepRules& step, const WeightTables& tables, const std::string& text,
                       int lo, int hi, ValidationReport& report, const std::string& at_parameters) {
  step.crease_ends.each([&](int d, int length, const std::optional<Rule>& slot) {
    if (!slot) return;
    const Rule& source = *slot;
    const CompiledRule& compiled =
        length == 0 ? tables.crease_ends.by_distance[size_t(d)] : tables.crease_ends.by_length.at(length)[size_t(d)];
    const std::string where = fmt::format("{} (crease, distance {}{})", placed(source.where, scheme.path, text), d,
                                          length == 0 ? "" : fmt::format(", length {}", length));
    for (int n = lo; n <= hi; ++n) {
      ++report.checks;
      const double sum = rule_sum(compiled, {n, 4, 0, 0}, Element::Vertex);
      if (!std::isfinite(sum) || std::abs(sum - 1) > 1e-9) {
        report.errors.push_back({not_affine(where, sum, fmt::format("n={}", n), at_parameters)});
        break;
      }
    }
  });
}

void check_step(const Scheme& scheme, const StepRules& step, const std::string& text, int lo, int hi,
                ValidationReport& report, const std::string& at_parameters = "") {
  const WeightTables tables = step_weight_tables(scheme, step, hi, 8, 0);
  const int face_size = natural_face_size(scheme);
  for (int e = 0; e < kElementCount; ++e)
    for (int c = 0; c < kContextCount; ++c) {
      if (!step.rules[e][c]) continue;  // engine defaults are affine by construction
      const CompiledRule& rule = tables.rules[e][c];
      const Rule& source = *step.rules[e][c];
      const std::string where =
          fmt::format("{} ({})", placed(source.where, scheme.path, text), context_name(Context(c)));
      if (Element(e) == Element::Face && uses_corner_roles(rule)) {
        check_corner_rule(rule, where, lo, hi, report, at_parameters);
        continue;
      }
      if (Element(e) == Element::Edge && reads_sectors(rule)) check_sector_rule(rule, where, lo, hi, report, at_parameters);
      bool reported = false;
      for (const Sizes& s : sizes_to_check(Element(e), lo, hi, face_size)) {
        ++report.checks;
        if (reported) continue;
        const double sum = rule_sum(rule, s, Element(e));
        const std::string at = Element(e) == Element::Edge ? fmt::format("n0={}, n1={}", s.n0, s.n1)
                               : Element(e) == Element::Vertex ? fmt::format("n={}", s.n)
                                                               : fmt::format("k={}", s.k);
        if (!std::isfinite(sum) || std::abs(sum - 1) > 1e-9) {
          report.errors.push_back({not_affine(where, sum, at, at_parameters)});
          reported = true;
        } else if (std::string why = asymmetry(rule, s, Element(e)); !why.empty()) {
          report.errors.push_back({fmt::format("{}: {} at {}{}", where, why, at, at_parameters)});
          reported = true;
        }
      }
    }
  check_crease_ends(scheme, step, tables, text, lo, hi, report, at_parameters);
}


// The values of one parameter the grid visits: every choice; for a numeric parameter with
// both bounds, its two ends (just inside an exclusive one) and three points between, or its
// whole numbers when the bounds and default are whole (degrees, repeat counts); else the default.
std::vector<std::string> grid_values(const ParameterSpec& p) {
  if (p.is_choice) return p.choices;
  auto text = [](double v) { return fmt::format("{:.17g}", v); };
  if (!p.has_minimum || !p.has_maximum || p.maximum <= p.minimum) return {text(p.value)};
  const auto whole = [](double v) { return std::floor(v) == v; };
  std::vector<std::string> out;
  if (whole(p.minimum) && whole(p.maximum) && whole(p.value)) {
    const double lo = p.minimum + p.minimum_exclusive, hi = p.maximum - p.maximum_exclusive;
    const double step = std::max(1.0, std::ceil((hi - lo) / 8));
    for (double v = lo; v < hi; v += step) out.push_back(text(v));
    if (hi >= lo) out.push_back(text(hi));
    return out;
  }
  const double span = p.maximum - p.minimum, inset = 1e-9 * span;
  const double lo = p.minimum + (p.minimum_exclusive ? inset : 0), hi = p.maximum - (p.maximum_exclusive ? inset : 0);
  for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) out.push_back(text(t == 1.0 ? hi : lo + t * (hi - lo)));
  return out;
}

// Grid points: the product of every parameter's values when it has at most 64 points, else
// each parameter swept on its own with the others at their defaults.
std::vector<ParameterOverrides> parameter_grid(const std::vector<ParameterSpec>& params) {
  std::vector<std::vector<std::string>> values;
  size_t product = 1;
  for (const ParameterSpec& p : params) {
    values.push_back(grid_values(p));
    product *= values.back().size();
  }
  std::vector<ParameterOverrides> grid;
  if (product <= 64) {
    grid.emplace_back();
    for (size_t i = 0; i < params.size(); ++i) {
      std::vector<ParameterOverrides> next;
      for (const auto& point : grid)
        for (const auto& v : values[i]) {
          next.push_back(point);
          next.back()[params[i].name] = v;
        }
      grid = std::move(next);
    }
    return grid;
  }
  for (size_t i = 0; i < params.size(); ++i)
    for (const auto& v : values[i]) grid.push_back({{params[i].name, v}});
  return grid;
}

std::string describe_point(const ParameterOverrides& point) {
  std::string out;
  for (const auto& [name, value] : point) out += fmt::format("{}{}={}", out.empty() ? " with " : ", ", name, value);
  return out;
}

// Checks the rules at every grid point of the parameters' declared ranges; stops at the
// first point that fails, which the messages name.
using SchemeMaker = std::function<std::shared_ptr<const Scheme>(const ParameterOverrides&)>;

void check_parameter_grid(const Scheme& scheme, const SchemeMaker& make, const std::string& text, int lo, int hi,
                          ValidationReport& report) {
  if (scheme.parameters.empty()) return;
  for (const ParameterOverrides& point : parameter_grid(scheme.parameters)) {
    const size_t before = report.errors.size();
    const std::string at = describe_point(point);
    try {
      const auto at_point = make(point);
      for (const auto& step : at_point->steps)
        if (!step.code && !step.nonlinear) check_step(*at_point, step, text, lo, hi, report, at);
    } catch (const Error& e) {
      report.errors.push_back({fmt::format("{}{}", e.what(), at)});
    }
    if (report.errors.size() > before) return;
  }
}

void check_curve(const CurveScheme& curve, const std::string& path, const std::string& text, ValidationReport& report) {
  FormulaSet formulas(curve.parameters, curve.definitions);
  if (curve.variational()) {  // K vanishes on constant polygons: alpha(1) = 0
    double sum = 0, magnitude = 0;
    for (size_t j = 0; j < curve.variational_alpha.size(); ++j) {
      const double a = formulas.evaluate(formulas.add(curve.variational_alpha[j], path), {0, 0, double(j)});
      sum += a, magnitude += std::abs(a);
    }
    ++report.checks;
    if (!(std::abs(sum) <= 1e-12 * magnitude))
      report.errors.push_back({fmt::format("{}:{}: variational.alpha sums to {}, not 0", path,
                                           line_of(text, curve.variational_alpha[0]), sum)});
  }
  for (size_t r = 0; r < curve.weights.size(); ++r) {
    double sum = 0;
    for (size_t t = 0; t < curve.weights[r].size(); ++t)
      sum += formulas.evaluate(formulas.add(curve.weights[r][t], path), {0, 0, double(t)});
    ++report.checks;
    if (std::abs(sum - 1) > 1e-9)
      report.errors.push_back({fmt::format("{}:{}: rules[{}]: weights sum to {}, not 1", path,
                                           line_of(text, curve.weights[r].empty() ? "" : curve.weights[r][0]), r, sum)});
  }
}

// A split step without any rule refines no mesh (the engine's defaults cover dart, crease and
// corner contexts only), yet nothing in it fails a weight check. Which elements need a rule
// depends on the mesh (a plugin's split may make edge points on boundaries only), so the
// check is for none at all; `refine` names the rule a mesh needs.
void check_rules_present(const Scheme& scheme, const StepRules& step, const std::string& text,
                         ValidationReport& report) {
  if (!step.is_split) return;
  for (const auto& by_context : step.rules)
    for (const auto& rule : by_context)
      if (rule) return;
  const SplitterInfo& split = splitter_info(step.split);
  std::string elements;
  for (const OriginKind kind : split.rule_elements)
    elements += fmt::format("{}rules.{}", elements.empty() ? "" : ", ", element_name(Element(int(kind))));
  const bool in_steps = step.where.rfind(scheme.path + ": ", 0) == 0;  // "FILE: steps[i]", else "FILE"
  const std::string where = in_steps ? step.where + ".rules" : scheme.path + ": rules";
  report.errors.push_back({fmt::format("{}: no rules, so the {} split's new points have no positions; add {} "
                                       "(docs/scheme-format.md)",
                                       placed(where, scheme.path, text), split.name, elements)});
}

void check_surface(const Scheme& scheme, const SchemeMaker& make, const std::string& text, int lo, int hi,
                   ValidationReport& report) {
  for (const auto& step : scheme.steps) {
    if (step.code || step.nonlinear) {
      report.skipped = fmt::format("{} has rules written in C++, which only a mesh can check", step.where.empty() ? scheme.name : step.where);
      continue;
    }
    check_rules_present(scheme, step, text, report);
    check_roles(scheme, step, text, report);
    check_step(scheme, step, text, lo, hi, report);
  }
  if (report.errors.empty()) check_parameter_grid(scheme, make, text, lo, hi, report);
  if (!has_feature_rules(scheme))
    report.notes.push_back("no boundary or crease rules (no \"curve\", no crease rule): closed meshes without "
                           "creases refine, but a mesh with a boundary, a crease or a UV seam is refused; name a "
                           "curve scheme with \"curve\" (\"cubic-bspline\" beside an approximating scheme, "
                           "\"four-point\" beside an interpolating one) to refine them");
}

// A scheme a plugin registered: its rules are data (a plugin's JSON scheme) or C++.
void validate_code_scheme(const CodeSchemeEntry& entry, int lo, int hi, ValidationReport& report) {
  report.kind = entry.kind;
  report.scheme_name = entry.name;
  if (entry.kind == "curve") {
    check_curve(*entry.make_curve({}, nullptr), entry.name, "", report);
    return;
  }
  check_surface(*entry.make_surface({}), entry.make_surface, "", lo, hi, report);
}

}  // namespace

ValidationReport validate_scheme_file(const std::string& name_or_path, int lo, int hi) {
  if (lo < kMinCheckedValence || hi > kMaxCheckedValence || lo > hi)
    throw OptionError(fmt::format("valences {}..{} cannot be checked: give {} <= {{min_valence}} <= {{max_valence}} <= {}", lo,
                            hi, kMinCheckedValence, kMaxCheckedValence));
  ValidationReport report;
  try {
    if (const CodeSchemeEntry* entry = find_code_scheme(name_or_path)) {
      validate_code_scheme(*entry, lo, hi, report);
      return report;
    }
    const std::string path = scheme_file_path(name_or_path);
    report.kind = scheme_file_kind(path);
    if (report.kind == "curve") {
      const auto curve = load_curve_scheme(path, {});
      report.scheme_name = curve->name;
      check_curve(*curve, path, read_text(path), report);
      return report;
    }
    const auto scheme = load_scheme(path);
    report.scheme_name = scheme->name;
    const std::string text = read_text(path);
    check_surface(*scheme, [&path](const ParameterOverrides& point) { return load_scheme(path, point); }, text, lo, hi,
                  report);
  } catch (const Error& e) {
    report.errors.push_back({e.what()});
  }
  return report;
}

}  // namespace subdiv
