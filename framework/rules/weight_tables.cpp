#include "framework/rules/weight_tables.h"

#include <algorithm>
#include <fmt/format.h>

#include "framework/util/error.h"
#include "framework/util/byte_size_text.h"
#include "framework/util/memory_limit.h"

namespace subdiv {
namespace {

constexpr int kVariables = 15;  // n, k, j, n0, n1, k0, k1, ci, cb, ex, fe, b0, b1, s0, s1
constexpr int kFirstSectorVariable = 11;

// Sizes and strides of the dense table over the variables a formula uses; end valences and
// sector slots over the ones present (end_count, slot_count).
struct TableShape {
  size_t size = 1;
  int count[kVariables] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
  size_t stride[kVariables] = {};
};

TableShape table_shape(const FormulaUses& uses, int max_n, int max_k, int max_j, int end_count, int slot_count) {
  TableShape s;
  // An end's flag b is m > 0 (sector_variables): with the end's sector slot tabulated, b
  // needs no dimension of its own.
  const bool slot0 = uses.m0 || uses.e0, slot1 = uses.m1 || uses.e1;
  const bool used[kVariables] = {uses.n,  uses.k,  uses.j,  uses.n0,           uses.n1,           uses.k0, uses.k1, uses.ci,
                                 uses.cb, uses.ex, uses.fe, uses.b0 && !slot0, uses.b1 && !slot1, slot0,   slot1};
  const int range[kVariables] = {max_n + 1, max_k + 1, max_j + 1, end_count, end_count, max_k + 1, max_k + 1,
                                 std::max(max_k, 1), 2, max_k + 1, max_k + 1, 2, 2, slot_count, slot_count};
  for (int v = kVariables - 1; v >= 0; --v) {
    if (!used[v]) continue;
    s.count[v] = range[v];
    s.stride[v] = s.size;
    s.size *= size_t(range[v]);
  }
  return s;
}

// The (m, e) pairs of the sector sizes m present, e = 0 .. m, in slot order, and each size's
// first slot (CompiledTerm::sector_slot).
struct SectorSlots {
  std::vector<std::pair<int, int>> pairs;
  std::vector<int> first;
};

SectorSlots sector_slots(const LevelValences* present, int max_n) {
  std::vector<int> sizes = {0};
  if (present) sizes.insert(sizes.end(), present->sector_sizes.begin(), present->sector_sizes.end());
  else
    for (int m = 1; m <= max_n; ++m) sizes.push_back(m);
  std::sort(sizes.begin(), sizes.end());
  sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
  SectorSlots out;
  out.first.assign(size_t(sizes.back()) + 1, 0);
  for (int m : sizes) {
    out.first[size_t(m)] = int(out.pairs.size());
    for (int e = 0; e <= m; ++e) out.pairs.emplace_back(m, e);
  }
  return out;
}

// A formula of the end valences n0, n1 and the index j is tabulated over all three: cubic
// in the largest valence (a 1,000-triangle fan asked for 7.9 GB that the memory guard did
// not see). Refused with the rule and the valence when it cannot fit.
void check_table_fits(const TableShape& shape, const std::string& where, int max_n) {
  const double bytes = double(shape.size) * sizeof(double);
  if (bytes < kUncheckedBytes) return;  // every term of every step comes here
  const MemoryBudget budget = available_memory();
  if (bytes > budget.bytes) {
    const auto [need_text, have_text] = byte_sizes_compared(bytes, budget.bytes);
    throw Error(fmt::format("{}: its weight table for valences up to {} has {} entries ({}), more than the {} of "
                            "memory this process may use ({}); the mesh's largest valence is too large for this rule",
                            where, max_n, shape.size, need_text, have_text, budget.source));
  }
}

// Calls visit(index into the table, coordinates) for every entry of a table of this shape,
// the last variable fastest; the index is kept as the coordinates turn (an odometer over the
// variables of more than one value), since tables reach millions of entries.
template <class Visit>
void for_each_entry(const int count[kVariables], const size_t stride[kVariables], Visit visit) {
  int turning[kVariables], turning_count = 0;
  for (int v = kVariables - 1; v >= 0; --v) {
    if (count[v] <= 0) return;
    if (count[v] > 1) turning[turning_count++] = v;
  }
  int x[kVariables] = {};
  size_t i = 0;
  for (;;) {
    visit(i, x);
    int d = 0;
    for (; d < turning_count; ++d) {
      const int v = turning[d];
      if (++x[v] < count[v]) {
        i += stride[v];
        break;
      }
      i -= stride[v] * size_t(count[v] - 1);
      x[v] = 0;
    }
    if (d == turning_count) return;
  }
}

// A formula may name a variable its value does not depend on (a definition that selects
// between cases by a parameter reads the variables of every case): such a dimension is
// dropped from the table, so that the kernels (smooth_kernels.h) see a weight that depends
// on n alone as such. The values stay the same.
void drop_constant_dimensions(CompiledTerm& t, const int count[kVariables]) {
  size_t* strides[kVariables] = {&t.stride_n,  &t.stride_k,  &t.stride_j,  &t.stride_n0, &t.stride_n1,
                                 &t.stride_k0, &t.stride_k1, &t.stride_ci, &t.stride_cb, &t.stride_ex,
                                 &t.stride_fe, &t.stride_b0, &t.stride_b1, &t.stride_s0, &t.stride_s1};
  size_t stride[kVariables];
  for (int v = 0; v < kVariables; ++v) stride[v] = *strides[v];
  // Constant along v: every entry equals its predecessor along v. One pass for all variables.
  bool constant[kVariables];
  for (int v = 0; v < kVariables; ++v) constant[v] = stride[v] != 0;
  for_each_entry(count, stride, [&](size_t i, const int* x) {
    for (int v = 0; v < kVariables; ++v)
      if (constant[v] && x[v] != 0 && t.table[i] != t.table[i - stride[v]]) constant[v] = false;
  });
  if (std::none_of(constant, constant + kVariables, [](bool c) { return c; })) return;
  int kept_count[kVariables];
  size_t kept_stride[kVariables] = {}, size = 1;
  for (int v = kVariables - 1; v >= 0; --v) {
    const bool keep = stride[v] != 0 && !constant[v];
    kept_count[v] = keep ? count[v] : 1;
    kept_stride[v] = keep ? size : 0;
    if (keep) size *= size_t(count[v]);
  }
  std::vector<double> kept(size);
  for_each_entry(kept_count, kept_stride, [&](size_t i, const int* x) {
    size_t from = 0;
    for (int v = 0; v < kVariables; ++v) from += stride[v] * size_t(x[v]);
    kept[i] = t.table[from];
  });
  t.table = std::move(kept);
  for (int v = 0; v < kVariables; ++v) *strides[v] = kept_stride[v];
}

bool is_end_sector(Role role) { return role == Role::EndSector0 || role == Role::EndSector1; }

// The largest index j of a role's points on a level: the edge roles of fixed size have 2 or 4
// points, an end's sector m + 1; the others at most the largest valence or face size, or a
// plugin role's own count.
int largest_point_index(Role role, int max_n, int max_k, int max_sector) {
  switch (role) {
    case Role::Ends:
    case Role::Opposite:
    case Role::Wings: return 1;
    case Role::FarWings: return 3;
    case Role::EndSector0:
    case Role::EndSector1: return max_sector;
    default: break;
  }
  int max_j = std::max(max_n, max_k);
  if (const RoleInfo* info = registered_role(role)) max_j = std::max(max_j, info->max_points(max_n, max_k) - 1);
  return max_j;
}

CompiledTerm compile_term(const Term& term, FormulaSet& formulas, const LevelValences* present, int max_n,
                          int max_k, int level) {
  CompiledTerm out;
  out.role = term.role;
  out.new_point = term.new_point;
  out.where = term.where;
  out.step = term.step;
  const int id = formulas.add(term.weight, term.where);
  const FormulaUses uses = formulas.uses(id);
  const bool reads_sectors = uses.m0 || uses.m1 || uses.e0 || uses.e1;
  const SectorSlots slots = reads_sectors || is_end_sector(term.role) ? sector_slots(present, max_n)
                                                                      : SectorSlots{{{0, 0}}, {0}};
  const int max_j = largest_point_index(term.role, max_n, max_k, int(slots.first.size()) - 1);
  out.max_j = max_j;
  out.reads_sector_sizes = reads_sectors || is_end_sector(term.role);
  // End valences: every valence up to max_n, or the ones present (valence_of[slot]).
  std::vector<int> valence_of;
  if (present && (uses.n0 || uses.n1)) {
    out.end_slot.assign(size_t(max_n) + 1, 0);
    for (int n : present->valences)
      if (n >= 0 && n <= max_n) out.end_slot[size_t(n)] = int(valence_of.size()), valence_of.push_back(n);
  }
  const int end_count = valence_of.empty() ? max_n + 1 : int(valence_of.size());
  auto end_valence = [&](int x) { return double(valence_of.empty() ? x : valence_of[size_t(x)]); };
  const TableShape shape = table_shape(uses, max_n, max_k, max_j, end_count, int(slots.pairs.size()));
  size_t* strides[kVariables] = {&out.stride_n,  &out.stride_k,  &out.stride_j,  &out.stride_n0, &out.stride_n1,
                                 &out.stride_k0, &out.stride_k1, &out.stride_ci, &out.stride_cb, &out.stride_ex,
                                 &out.stride_fe, &out.stride_b0, &out.stride_b1, &out.stride_s0, &out.stride_s1};
  for (int v = 0; v < kVariables; ++v) *strides[v] = shape.stride[v];
  check_table_fits(shape, term.where, max_n);
  out.table.resize(shape.size);
  for_each_entry(shape.count, shape.stride, [&](size_t i, const int* x) {
    const auto [m0, e0] = slots.pairs[size_t(x[13])];
    const auto [m1, e1] = slots.pairs[size_t(x[14])];
    // b from its own dimension, or from the slot's m when the slot stands for it (table_shape).
    const double b0 = double(x[11] || m0 > 0), b1 = double(x[12] || m1 > 0);
    out.table[i] = formulas.evaluate(id, {double(x[0]), double(x[1]), double(x[2]), double(level), end_valence(x[3]),
                                          end_valence(x[4]), double(x[5]), double(x[6]), double(x[7]), double(x[8]),
                                          double(x[9]), double(x[10]), b0, b1, double(m0), double(m1), double(e0),
                                          double(e1)});
    if (std::all_of(x + kFirstSectorVariable, x + kVariables, [](int v) { return v == 0; }) && out.table[i] != 0.0)
      out.zero_without_sectors = false;
  });
  drop_constant_dimensions(out, shape.count);
  if (out.stride_n0 == 0 && out.stride_n1 == 0) out.end_slot.clear();
  if (out.stride_s0 || out.stride_s1) out.sector_slot = slots.first;
  return out;
}

CompiledRule compile_rule(const Rule& rule, FormulaSet& formulas, const LevelValences* present, int max_n, int max_k,
                          int level) {
  CompiledRule out;
  out.where = rule.where;
  out.defined = true;
  for (const Term& term : rule.terms) out.terms.push_back(compile_term(term, formulas, present, max_n, max_k, level));
  return out;
}

}  // namespace

CompiledRule compile_curve_rule(const CurveRuleText& rule, const FormulaScope& scope, int level) {
  static const std::vector<NamedFormula> none;
  FormulaSet formulas(scope.parameters, scope.definitions ? *scope.definitions : none);
  CompiledTerm term;
  term.role = Role::Curve;
  term.where = rule.where;
  term.curve_start = rule.start;
  for (size_t t = 0; t < rule.weights.size(); ++t) {
    const int id = formulas.add(rule.weights[t], fmt::format("{}[{}]", term.where, t));
    term.curve_weights.push_back(formulas.evaluate(id, {0, 0, double(t), double(level)}));
  }
  CompiledRule out;
  out.where = term.where;
  out.defined = true;
  out.terms.push_back(std::move(term));
  return out;
}

CompiledRule stay_rule() {
  CompiledTerm self;
  self.role = Role::Self;
  self.where = "engine default: the point stays";
  self.table = {1.0};
  CompiledRule out;
  out.where = self.where;
  out.defined = true;
  out.terms.push_back(std::move(self));
  return out;
}

CreaseEndTable<CompiledRule> compile_crease_end_rules(const CreaseEndRules& rules, const FormulaScope& scope, int max_n,
                                                      int max_k, int level) {
  static const std::vector<NamedFormula> none;
  FormulaSet formulas(scope.parameters, scope.definitions ? *scope.definitions : none);
  auto compiled = [&](const std::vector<std::optional<Rule>>& slots) {
    std::vector<CompiledRule> out(slots.size());
    for (size_t d = 0; d < slots.size(); ++d)
      if (slots[d]) out[d] = compile_rule(*slots[d], formulas, scope.present, max_n, max_k, level);
    return out;
  };
  CreaseEndTable<CompiledRule> out;
  out.by_distance = compiled(rules.by_distance);
  for (const auto& entry : rules.by_length) out.by_length[entry.first] = compiled(entry.second);
  return out;
}

bool reads_sector_sizes(const WeightTables& tables) {
  auto reads = [](const CompiledRule& rule) {
    return std::any_of(rule.terms.begin(), rule.terms.end(), [](const CompiledTerm& t) { return t.reads_sector_sizes; });
  };
  for (const auto& by_context : tables.rules)
    for (const CompiledRule& rule : by_context)
      if (reads(rule)) return true;
  for (const CompiledRule& rule : tables.crease_ends.by_distance)
    if (reads(rule)) return true;
  for (const auto& entry : tables.crease_ends.by_length)
    for (const CompiledRule& rule : entry.second)
      if (reads(rule)) return true;
  return false;
}

WeightTables compile_rule_table(const RuleTable& rules, const FormulaScope& scope, int max_n, int max_k, int level) {
  WeightTables tables;
  tables.max_n = max_n, tables.max_k = max_k;
  static const std::vector<NamedFormula> none;
  FormulaSet formulas(scope.parameters, scope.definitions ? *scope.definitions : none);
  for (int e = 0; e < kElementCount; ++e) {
    // Face and corner rules read n as the face size (docs/scheme-format.md), which can
    // exceed the largest valence: a cube's quads among valence-3 vertices.
    const bool n_is_face_size = Element(e) == Element::Face || Element(e) == Element::Corner;
    const int rule_max_n = n_is_face_size ? std::max(max_n, max_k) : max_n;
    for (int c = 0; c < kContextCount; ++c)
      if (rules[e][c])
        tables.rules[e][c] = compile_rule(*rules[e][c], formulas, scope.present, rule_max_n, max_k, level);
  }

  for (Element e : {Element::Vertex, Element::Corner}) {
    auto& r = tables.rules[int(e)];
    if (!r[int(Context::Dart)].defined) r[int(Context::Dart)] = r[int(Context::Smooth)];
    if (!r[int(Context::Corner)].defined) r[int(Context::Corner)] = stay_rule();
  }
  return tables;
}

}  // namespace subdiv
