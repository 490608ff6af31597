#include "framework/rules/formula.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <deque>
#include <fmt/format.h>
#include <limits>
#include <muParser.h>

#include "framework/rules/definition_order.h"
#include "framework/util/error.h"
#include "framework/util/short_text.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

constexpr const char* kFormulaHelp =
    "Formulas may use n, k, j, l (edge rules also n0, n1, k0, k1, b0, b1, m0, m1, e0, e1; face rules ci, cb, ex, fe), the scheme's parameters, state and definitions, muParser "
    "functions such as cos, sqrt, min, max, the functions binom(a, b), floor, ceil, mod(a, b), "
    "and the constant pi";

// State variables are followed level by level from l = 0 and kept for every level, so a
// level of 2^31 would take minutes and gigabytes before the first weight. Refinement stops at
// level 130 (30 levels after a start level of at most 100); a million levels is far past
// where a non-stationary scheme's state has settled to round-off.
constexpr double kMaxStateLevel = 1'000'000;

bool whole(double x) { return std::isfinite(x) && x == std::floor(x); }

double floor_fn(double x) { return std::floor(x); }
double ceil_fn(double x) { return std::ceil(x); }
double mod_fn(double a, double b) { return a - b * std::floor(a / b); }
double binom_fn(double a, double b) { return binomial_coefficient(a, b); }

std::vector<size_t> ascending_unique(std::vector<size_t> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

}  // namespace

double binomial_coefficient(double a, double b) {
  if (!whole(b) || !std::isfinite(a)) return std::numeric_limits<double>::quiet_NaN();
  if (b < 0) return 0.0;
  if (whole(a) && a >= 0 && b > a) return 0.0;
  if (whole(a) && a >= 0 && b > a / 2) b = a - b;  // symmetry: fewer factors, same value
  double c = 1.0;
  for (double i = 1; i <= b; ++i) c = c * (a - b + i) / i;
  // Whole arguments give whole coefficients; remove the round-off of the divisions.
  return whole(a) ? std::round(c) : c;
}

struct FormulaSet::Impl {
  // Variable storage must not move: muParser keeps pointers to it.
  double n = 0, k = 0, j = 0, l = 0, n0 = 0, n1 = 0, k0 = 0, k1 = 0;
  double ci = 0, cb = 0, ex = 0, fe = 0;
  double b0 = 0, b1 = 0, m0 = 0, m1 = 0, e0 = 0, e1 = 0;
  std::map<std::string, double> parameters;

  // State variables: initial and next parsers, the storage formulas read, and the values
  // per level computed so far.
  std::vector<std::string> state_names, state_wheres;
  std::vector<FormulaUses> state_uses;  // what each state variable's formulas read
  std::deque<double> state_storage;
  std::vector<std::unique_ptr<mu::Parser>> state_initial, state_next;
  std::vector<std::vector<double>> state_by_level;

  std::deque<double> definition_values;
  std::vector<std::unique_ptr<mu::Parser>> definitions;
  std::vector<FormulaUses> definition_uses;
  // The definitions each definition and formula reads, directly or through another, ascending:
  // only these are evaluated before it (a scheme's definitions may be many, with cosines).
  std::vector<std::vector<size_t>> definition_reads, formula_reads;
  std::vector<std::string> definition_names, definition_wheres, definition_expressions;
  std::vector<std::unique_ptr<mu::Parser>> formulas;
  std::vector<FormulaUses> formula_uses;
  std::vector<std::string> wheres, expressions;

  // visible_state: how many state variables the expression sees; visible_definitions
  // likewise for plain definitions.
  std::unique_ptr<mu::Parser> compile(const std::string& expression, const std::string& where,
                                      size_t visible_state, size_t visible_definitions,
                                      FormulaUses& uses, std::vector<size_t>* reads = nullptr) {
    auto parser = std::make_unique<mu::Parser>();
    try {
      parser->DefineVar("n", &n);
      parser->DefineVar("k", &k);
      parser->DefineVar("j", &j);
      parser->DefineVar("l", &l);
      parser->DefineVar("n0", &n0);
      parser->DefineVar("n1", &n1);
      parser->DefineVar("k0", &k0);
      parser->DefineVar("k1", &k1);
      parser->DefineVar("ci", &ci);
      parser->DefineVar("cb", &cb);
      parser->DefineVar("ex", &ex);
      parser->DefineVar("fe", &fe);
      parser->DefineVar("b0", &b0);
      parser->DefineVar("b1", &b1);
      parser->DefineVar("m0", &m0);
      parser->DefineVar("m1", &m1);
      parser->DefineVar("e0", &e0);
      parser->DefineVar("e1", &e1);
      parser->DefineConst("pi", 3.14159265358979323846);
      parser->DefineFun("binom", binom_fn);
      parser->DefineFun("floor", floor_fn);
      parser->DefineFun("ceil", ceil_fn);
      parser->DefineFun("mod", mod_fn);
      for (auto& [name, value] : parameters) parser->DefineVar(name, &value);
      for (size_t i = 0; i < visible_state; ++i) parser->DefineVar(state_names[i], &state_storage[i]);
      for (size_t i = 0; i < visible_definitions; ++i)
        parser->DefineVar(definition_names[i], &definition_values[i]);
      parser->SetExpr(expression);
      for (const auto& [name, ptr] : parser->GetUsedVar()) {
        uses.n |= name == "n", uses.k |= name == "k", uses.j |= name == "j", uses.l |= name == "l";
        uses.n0 |= name == "n0", uses.n1 |= name == "n1", uses.k0 |= name == "k0", uses.k1 |= name == "k1";
        uses.ci |= name == "ci", uses.cb |= name == "cb", uses.ex |= name == "ex", uses.fe |= name == "fe";
        uses.b0 |= name == "b0", uses.b1 |= name == "b1", uses.m0 |= name == "m0", uses.m1 |= name == "m1";
        uses.e0 |= name == "e0", uses.e1 |= name == "e1";
        if (parameters.count(name) && !uses.reads(name)) uses.parameters.push_back(name);
        for (size_t i = 0; i < visible_definitions; ++i) {
          if (definition_names[i] != name) continue;
          uses.merge(definition_uses[i]);
          if (!reads) continue;
          reads->push_back(i);
          reads->insert(reads->end(), definition_reads[i].begin(), definition_reads[i].end());
        }
        for (size_t i = 0; i < visible_state && i < state_uses.size(); ++i)
          if (state_names[i] == name) uses.merge(state_uses[i]);
      }
    } catch (const mu::Parser::exception_type& e) {
      throw Error(fmt::format("{}: formula {} does not parse: {}. {}", where, subdiv::quoted(shortened(expression)),
                              shortened(e.GetMsg(), 2 * kQuotedTextChars),
                              kFormulaHelp));
    }
    for (const auto& [name, ptr] : parser->GetUsedVar()) {
      // GetUsedVar lists a name nothing defines with no storage. Said here, when the scheme is
      // loaded, rather than as muParser's "Unexpected token" at the first valence evaluated.
      // muParser reads a number it cannot hold in a double (1e400) as a name.
      if (ptr == nullptr && (std::isdigit(static_cast<unsigned char>(name[0])) || name[0] == '.'))
        throw Error(fmt::format("{}: formula {} has the number {}, which a double cannot hold (its magnitude must be "
                                "below about 1.8e308, and 0 or above about 2.2e-308): write the number within that "
                                "range",
                                where, subdiv::quoted(shortened(expression)), subdiv::quoted(name)));
      if (ptr == nullptr)
        throw Error(fmt::format("{}: formula {} uses {}, which is not defined: declare it under \"parameters\" "
                                "(with a default) or \"definitions\" (before this use), or correct its spelling. {}",
                                where, subdiv::quoted(shortened(expression)), subdiv::quoted(name), kFormulaHelp));
      // State variables change with the level: a formula that reads one depends on l.
      for (size_t i = 0; i < visible_state; ++i) uses.l |= state_names[i] == name;
    }
    return parser;
  }

  void add_state(const NamedFormula& d) {
    if (!definitions.empty())
      throw Error(fmt::format("{}: state variable {} comes after a plain definition; state must "
                              "come first", d.where, subdiv::quoted(d.name)));
    // The initial value sees the earlier state variables only.
    FormulaUses uses;
    auto initial = compile(d.expression, d.where, state_names.size(), 0, uses);
    check_state_uses(uses, d.name, d.where);
    state_uses.push_back(uses);
    state_names.push_back(d.name);
    state_wheres.push_back(d.where);
    state_storage.push_back(0.0);
    state_initial.push_back(std::move(initial));
    state_next.push_back(nullptr);
    pending_next.push_back(d);
  }

  // Recurrences see every state variable, so they are compiled once all are declared.
  std::vector<NamedFormula> pending_next;

  void finish_state() {
    for (const auto& d : pending_next) {
      const size_t i = size_t(&d - pending_next.data()) + state_names.size() - pending_next.size();
      const std::string& where = d.next_where.empty() ? d.where : d.next_where;
      FormulaUses uses;
      state_next[i] = compile(d.next, where, state_names.size(), 0, uses);
      check_state_uses(uses, d.name, where);
      state_uses[i].merge(uses);
    }
    pending_next.clear();
  }

  static void check_state_uses(const FormulaUses& uses, const std::string& name, const std::string& where) {
    if (uses.n || uses.k || uses.j)
      throw Error(fmt::format("{}: state variable {} depends on {}; state is one value per level and "
                              "may use only parameters, l and state variables",
                              where, subdiv::quoted(name), uses.n ? "n" : uses.k ? "k" : "j"));
  }

  // Fills state_by_level up to `level` and loads that level's values into the storage.
  void load_state(double level_value) {
    if (state_names.empty()) return;
    if (!whole(level_value) || level_value < 0)
      throw Error(fmt::format("state variables are defined on whole levels l >= 0, not l = {}", level_value));
    if (level_value > kMaxStateLevel)
      throw Error(fmt::format("{}: state variable {} is followed level by level from l = 0, and level {} is beyond "
                              "the {} levels that are followed; ask for a level up to {} (the state has settled "
                              "long before)",
                              state_wheres[0], subdiv::quoted(state_names[0]), level_value, kMaxStateLevel,
                              kMaxStateLevel));
    const size_t level = size_t(level_value);
    const double saved_l = l;
    try {
      if (state_by_level.empty()) {
        l = 0;
        std::vector<double> initial(state_names.size());
        for (size_t i = 0; i < state_names.size(); ++i) {
          initial[i] = state_initial[i]->Eval();
          state_storage[i] = initial[i];
          check_finite(initial[i], i, 0);
        }
        state_by_level.push_back(std::move(initial));
      }
      while (state_by_level.size() <= level) {
        const size_t from = state_by_level.size() - 1;
        l = double(from);
        for (size_t i = 0; i < state_names.size(); ++i) state_storage[i] = state_by_level[from][i];
        std::vector<double> next(state_names.size());
        for (size_t i = 0; i < state_names.size(); ++i) next[i] = state_next[i]->Eval();
        for (size_t i = 0; i < state_names.size(); ++i) check_finite(next[i], i, from + 1);
        state_by_level.push_back(std::move(next));
      }
    } catch (const mu::Parser::exception_type& e) {
      l = saved_l;
      throw Error(fmt::format("state variables fail to evaluate up to level {}: {}", level,
                              shortened(e.GetMsg(), 2 * kQuotedTextChars)));
    }
    l = saved_l;
    for (size_t i = 0; i < state_names.size(); ++i) state_storage[i] = state_by_level[level][i];
  }

  void check_finite(double value, size_t i, size_t level) const {
    if (!std::isfinite(value))
      throw Error(fmt::format("{}: state variable {} is {} at level {}; check its initial value, its "
                              "recurrence \"next\" and the parameters' ranges",
                              state_wheres[i], subdiv::quoted(state_names[i]), value, level));
  }

  // A definition that fails is named with its own place, not only the formula reading it
  // (muParser reports a definition's syntax error when it first evaluates it).
  void evaluate_definitions(const std::vector<size_t>& reads, const std::string& reader) {
    load_state(l);
    for (size_t i : reads) {
      try {
        definition_values[i] = definitions[i]->Eval();
      } catch (const mu::Parser::exception_type& e) {
        throw Error(fmt::format("{}: definition {} = {} fails to evaluate at n={}, k={}, j={}, l={}: {} "
                                "(while evaluating {}, which sees the definitions)",
                                definition_wheres[i], subdiv::quoted(definition_names[i]), subdiv::quoted(shortened(definition_expressions[i])), n, k,
                                j, l, shortened(e.GetMsg(), 2 * kQuotedTextChars), reader));
      }
    }
  }
};

FormulaSet::FormulaSet(const std::map<std::string, double>& parameters,
                       const std::vector<NamedFormula>& definitions)
    : impl_(std::make_unique<Impl>()) {
  impl_->parameters = parameters;
  check_definition_order(definitions);  // cycles and forward uses, named as such
  for (const auto& d : definitions) {
    if (d.is_state()) {
      impl_->add_state(d);
      continue;
    }
    impl_->finish_state();
    FormulaUses uses;
    std::vector<size_t> reads;
    auto parser =
        impl_->compile(d.expression, d.where, impl_->state_names.size(), impl_->definitions.size(), uses, &reads);
    impl_->definitions.push_back(std::move(parser));
    impl_->definition_reads.push_back(ascending_unique(std::move(reads)));
    impl_->definition_uses.push_back(uses);
    impl_->definition_names.push_back(d.name);
    impl_->definition_wheres.push_back(d.where);
    impl_->definition_expressions.push_back(d.expression);
    impl_->definition_values.push_back(0.0);
  }
  impl_->finish_state();
}

FormulaSet::~FormulaSet() = default;

int FormulaSet::add(const std::string& expression, const std::string& where) {
  FormulaUses uses;
  std::vector<size_t> reads;
  auto parser = impl_->compile(expression, where, impl_->state_names.size(), impl_->definitions.size(), uses, &reads);
  impl_->formulas.push_back(std::move(parser));
  impl_->formula_reads.push_back(ascending_unique(std::move(reads)));
  impl_->formula_uses.push_back(uses);
  impl_->wheres.push_back(where);
  impl_->expressions.push_back(expression);
  return int(impl_->formulas.size()) - 1;
}

double FormulaSet::evaluate(int id, const FormulaInputs& in) {
  impl_->n = in.n, impl_->k = in.k, impl_->j = in.j, impl_->l = in.l, impl_->n0 = in.n0, impl_->n1 = in.n1;
  impl_->k0 = in.k0, impl_->k1 = in.k1;
  impl_->ci = in.ci, impl_->cb = in.cb, impl_->ex = in.ex, impl_->fe = in.fe;
  impl_->b0 = in.b0, impl_->b1 = in.b1, impl_->m0 = in.m0, impl_->m1 = in.m1, impl_->e0 = in.e0, impl_->e1 = in.e1;
  impl_->evaluate_definitions(impl_->formula_reads[id], impl_->wheres[id]);
  try {
    return impl_->formulas[id]->Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw Error(fmt::format("{}: formula {} fails to evaluate at n={}, k={}, j={}, l={}: {}",
                            impl_->wheres[id], subdiv::quoted(shortened(impl_->expressions[id])), in.n, in.k, in.j, in.l,
                            shortened(e.GetMsg(), 2 * kQuotedTextChars)));
  }
}

std::vector<double> FormulaSet::state_values(int level) {
  impl_->load_state(double(level));
  if (impl_->state_names.empty()) return {};
  return impl_->state_by_level[size_t(level)];
}

void FormulaUses::merge(const FormulaUses& o) {
  n |= o.n, k |= o.k, j |= o.j, l |= o.l, n0 |= o.n0, n1 |= o.n1, k0 |= o.k0, k1 |= o.k1;
  ci |= o.ci, cb |= o.cb, ex |= o.ex, fe |= o.fe;
  b0 |= o.b0, b1 |= o.b1, m0 |= o.m0, m1 |= o.m1, e0 |= o.e0, e1 |= o.e1;
  for (const std::string& p : o.parameters)
    if (!reads(p)) parameters.push_back(p);
}

bool FormulaUses::reads(const std::string& parameter) const {
  return std::find(parameters.begin(), parameters.end(), parameter) != parameters.end();
}

FormulaUses FormulaSet::uses(int id) const { return impl_->formula_uses[id]; }
const std::string& FormulaSet::where(int id) const { return impl_->wheres[id]; }
const std::string& FormulaSet::expression(int id) const { return impl_->expressions[id]; }

}  // namespace subdiv
