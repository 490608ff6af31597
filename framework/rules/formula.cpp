#include "framework/rules/formula.h"

#include <deque>
#include <fmt/format.h>
#include <muParser.h>

#include "framework/util/error.h"

namespace subdiv {

struct FormulaSet::Impl {
  // Variable storage must not move: muParser keeps pointers to it.
  double n = 0, k = 0, j = 0, l = 0, n0 = 0, n1 = 0;
  std::map<std::string, double> parameters;
  std::deque<double> definition_values;
  std::vector<std::unique_ptr<mu::Parser>> definitions;
  std::vector<FormulaUses> definition_uses;
  std::vector<std::string> definition_names;
  std::vector<std::unique_ptr<mu::Parser>> formulas;
  std::vector<FormulaUses> formula_uses;
  std::vector<std::string> wheres, expressions;

  std::unique_ptr<mu::Parser> compile(const std::string& expression, const std::string& where,
                                      size_t visible_definitions, FormulaUses& uses) {
    auto parser = std::make_unique<mu::Parser>();
    try {
      parser->DefineVar("n", &n);
      parser->DefineVar("k", &k);
      parser->DefineVar("j", &j);
      parser->DefineVar("l", &l);
      parser->DefineVar("n0", &n0);
      parser->DefineVar("n1", &n1);
      parser->DefineConst("pi", 3.14159265358979323846);
      for (auto& [name, value] : parameters) parser->DefineVar(name, &value);
      for (size_t i = 0; i < visible_definitions; ++i)
        parser->DefineVar(definition_names[i], &definition_values[i]);
      parser->SetExpr(expression);
      for (const auto& [name, ptr] : parser->GetUsedVar()) {
        uses.n |= name == "n", uses.k |= name == "k", uses.j |= name == "j", uses.l |= name == "l";
        uses.n0 |= name == "n0", uses.n1 |= name == "n1";
        for (size_t i = 0; i < visible_definitions; ++i) {
          if (definition_names[i] != name) continue;
          const FormulaUses& d = definition_uses[i];
          uses.n |= d.n, uses.k |= d.k, uses.j |= d.j, uses.l |= d.l, uses.n0 |= d.n0, uses.n1 |= d.n1;
        }
      }
    } catch (const mu::Parser::exception_type& e) {
      throw Error(fmt::format("{}: formula '{}' does not parse: {}. Formulas may use n, k, j, l, "
                              "the scheme's parameters and definitions, and muParser functions "
                              "such as cos, sqrt, and the constant pi",
                              where, expression, e.GetMsg()));
    }
    return parser;
  }

  void evaluate_definitions() {
    for (size_t i = 0; i < definitions.size(); ++i) definition_values[i] = definitions[i]->Eval();
  }
};

FormulaSet::FormulaSet(const std::map<std::string, double>& parameters,
                       const std::vector<NamedFormula>& definitions)
    : impl_(std::make_unique<Impl>()) {
  impl_->parameters = parameters;
  for (const auto& d : definitions) {
    FormulaUses uses;
    auto parser = impl_->compile(d.expression, d.where, impl_->definitions.size(), uses);
    impl_->definitions.push_back(std::move(parser));
    impl_->definition_uses.push_back(uses);
    impl_->definition_names.push_back(d.name);
    impl_->definition_values.push_back(0.0);
  }
}

FormulaSet::~FormulaSet() = default;

int FormulaSet::add(const std::string& expression, const std::string& where) {
  FormulaUses uses;
  auto parser = impl_->compile(expression, where, impl_->definitions.size(), uses);
  impl_->formulas.push_back(std::move(parser));
  impl_->formula_uses.push_back(uses);
  impl_->wheres.push_back(where);
  impl_->expressions.push_back(expression);
  return int(impl_->formulas.size()) - 1;
}

double FormulaSet::evaluate(int id, const FormulaInputs& in) {
  impl_->n = in.n, impl_->k = in.k, impl_->j = in.j, impl_->l = in.l, impl_->n0 = in.n0, impl_->n1 = in.n1;
  try {
    impl_->evaluate_definitions();
    return impl_->formulas[id]->Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw Error(fmt::format("{}: formula '{}' fails to evaluate at n={}, k={}, j={}, l={}: {}",
                            impl_->wheres[id], impl_->expressions[id], in.n, in.k, in.j, in.l,
                            e.GetMsg()));
  }
}

FormulaUses FormulaSet::uses(int id) const { return impl_->formula_uses[id]; }
const std::string& FormulaSet::where(int id) const { return impl_->wheres[id]; }
const std::string& FormulaSet::expression(int id) const { return impl_->expressions[id]; }

}  // namespace subdiv
