#pragma once
// A scheme's named definitions may use only the ones before them. A definition that uses
// itself or a later one would reach muParser as an unknown name ("Unexpected token"),
// which hides the real problem; this check names it first: a cycle (a -> b -> a) or a
// use before the definition, with the place of the definition in the scheme file.
#include <vector>

#include "framework/rules/formula.h"

namespace subdiv {

// Throws subdiv::Error naming the first cycle, else the first use of a later definition.
// State recurrences ("next") may use every state variable, themselves included, and are
// not checked here.
void check_definition_order(const std::vector<NamedFormula>& definitions);

}  // namespace subdiv
