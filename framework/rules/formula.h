#pragma once
// Weight formulas (muParser). A formula may use n (valence or face size), k (size of the
// face the point belongs to), j (index of the point within its role), l (level), n0 and
// n1 (valences of an edge's two ends, in edge rules), the
// scheme's numeric parameters, and the scheme's named definitions. Formulas are evaluated
// only while weight tables are prepared, never per vertex; a FormulaSet is not thread-safe.
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace subdiv {

struct FormulaInputs {
  double n = 0, k = 0, j = 0, l = 0, n0 = 0, n1 = 0;
};

// Which of n, k, j, l, n0, n1 a formula depends on (through definitions too).
struct FormulaUses {
  bool n = false, k = false, j = false, l = false, n0 = false, n1 = false;
};

struct NamedFormula {
  std::string name, expression, where;
};

class FormulaSet {
public:
  // `definitions` are evaluated in order before each formula; each may use the earlier ones.
  // `where` strings name the place in the scheme file for error messages.
  FormulaSet(const std::map<std::string, double>& parameters,
             const std::vector<NamedFormula>& definitions);
  ~FormulaSet();
  FormulaSet(const FormulaSet&) = delete;
  FormulaSet& operator=(const FormulaSet&) = delete;

  // Compiles an expression; throws subdiv::Error naming `where` if it does not parse or
  // names an unknown variable.
  int add(const std::string& expression, const std::string& where);
  double evaluate(int id, const FormulaInputs& inputs);
  FormulaUses uses(int id) const;
  const std::string& where(int id) const;
  const std::string& expression(int id) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace subdiv
