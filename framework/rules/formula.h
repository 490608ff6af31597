#pragma once
// Weight formulas (muParser). A formula may use n (valence or face size), k (size of the
// face the point belongs to), j (index of the point within its role), l (level), n0 and
// n1 (valences of an edge's two ends, in edge rules), k0 and k1 (sizes of an edge's two
// faces, 0 where there is none, in edge rules: OpenSubdiv's smooth-triangle weights), the
// face rules' corner variables ci, cb, ex and fe (weight_tables.h), the edge rules' sector
// variables b0, b1, m0, m1, e0, e1 (element_rules.h: EdgeSectors), the
// scheme's numeric parameters, and the scheme's named definitions. Formulas are evaluated
// only while weight tables are prepared, never per vertex; a FormulaSet is not thread-safe.
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace subdiv {

struct FormulaInputs {
  double n = 0, k = 0, j = 0, l = 0, n0 = 0, n1 = 0, k0 = 0, k1 = 0;
  // Face rules (the corner roles): the corner's index, whether its vertex is on a boundary
  // or crease, the face's number of extraordinary corners and of feature edges.
  double ci = 0, cb = 0, ex = 0, fe = 0;
  // Edge rules (the end-sector roles): per end, 1 when it is a feature vertex whose sector
  // holds the edge, that sector's number of faces, and the edge's index in it (0 elsewhere).
  double b0 = 0, b1 = 0, m0 = 0, m1 = 0, e0 = 0, e1 = 0;
};

// Which of n, k, j, l, n0, n1, k0, k1 a formula depends on (through definitions too).
struct FormulaUses {
  bool n = false, k = false, j = false, l = false, n0 = false, n1 = false, k0 = false, k1 = false;
  bool ci = false, cb = false, ex = false, fe = false;
  bool b0 = false, b1 = false, m0 = false, m1 = false, e0 = false, e1 = false;
  // The scheme parameters it reads, directly or through definitions and state variables
  // (per-vertex parameters may only be read by vertex rules: scheme_loader.cpp).
  std::vector<std::string> parameters;

  void merge(const FormulaUses& other);
  bool reads(const std::string& parameter) const;
};

// Besides muParser's built-in functions (sin, cos, sqrt, exp, abs, min, max, rint, ...)
// formulas may call binom(a, b), floor(x), ceil(x) and mod(a, b), and use the scheme's
// level-dependent state variables (non-stationary schemes, e.g. the tension alpha_k of
// Morin, Warren & Weimer 2001). A NamedFormula whose `next` is not empty is a state variable. Its value
// while level l is refined (the step from level l to level l + 1) is
//     x(0)     = expression, evaluated with l = 0,
//     x(l + 1) = next, evaluated with l and every state variable at their step-l values.
// State variables come before the plain definitions; `expression` may use parameters and
// earlier state variables, `next` may use parameters, l and all state variables; neither
// may use n, k or j. Every formula that uses a state variable counts as using l.
struct NamedFormula {
  std::string name, expression, where;
  std::string next;        // state variables only: the recurrence (see above)
  std::string next_where;  // its place in the scheme file
  bool is_state() const { return !next.empty(); }
};

// binom(a, b): the binomial coefficient a(a-1)...(a-b+1)/b! for a whole number b >= 0
// (any real a; 0 for whole 0 <= a < b); 0 for a whole b < 0; NaN when b is not whole.
double binomial_coefficient(double a, double b);

class FormulaSet {
public:
  // `definitions` are evaluated in order before each formula; each may use the earlier ones.
  // `where` strings name the place in the scheme file for error messages. Throws
  // subdiv::Error for a definition or state formula that does not parse, state after a
  // plain definition, or state that depends on n, k or j.
  FormulaSet(const std::map<std::string, double>& parameters,
             const std::vector<NamedFormula>& definitions);
  ~FormulaSet();
  FormulaSet(const FormulaSet&) = delete;
  FormulaSet& operator=(const FormulaSet&) = delete;

  // Compiles an expression; throws subdiv::Error naming `where` if it does not parse or
  // names an unknown variable.
  int add(const std::string& expression, const std::string& where);
  // Throws subdiv::Error if evaluation fails or a state variable is not finite at level l
  // (l must be a whole number >= 0). The result itself may be NaN: callers check.
  double evaluate(int id, const FormulaInputs& inputs);
  FormulaUses uses(int id) const;
  const std::string& where(int id) const;
  const std::string& expression(int id) const;

  // The state variables' values while level `level` is refined, in declaration order.
  std::vector<double> state_values(int level);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace subdiv
