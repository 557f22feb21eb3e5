#pragma once
// constraints[i] of type `expression`: a user-defined constraint f(x, t) = 0 written as
// an expression of named joint coordinates (docs/case-format.md).
#include <string>

#include "app/case/case_definition.hpp"
#include "app/case/expression.hpp"
#include "app/case/node_reader.hpp"

namespace heavesim {

/// Reads one such item (its name already read and checked unique) into
/// definition.expression_constraints: its `variables` (a joint name, or {joint,
/// coordinate}) and its `expression`, parsed here with the case's parameters so that a
/// syntax error, an unknown symbol, a variable the expression does not read or an
/// expression that reads no coordinate is bad input at its key; so is a name that is not
/// a joint of the tree (with a did-you-mean). The joints' types and coordinates are
/// checked by the model builder, whose ModelError names the key `variables.<symbol>`.
/// Throws InputError.
void read_expression_constraint(const NodeReader& item, const std::string& name, CaseDefinition& definition,
                                const ExpressionContext& expressions);

}  // namespace heavesim
