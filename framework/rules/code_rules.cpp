#include "framework/rules/code_rules.h"

#include "framework/rules/row_builder.h"

namespace subdiv {

void RowWriter::add(Index parent_vertex, double weight) { row_.add(parent_vertex, scale_ * weight); }

}  // namespace subdiv
