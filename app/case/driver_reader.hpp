#pragma once
// drivers[i] of a case: prescribed motions as constraints (docs/case-format.md).
#include <string>

#include "app/case/case_definition.hpp"
#include "app/case/expression.hpp"
#include "app/case/node_reader.hpp"

namespace heavesim {

/// Reads one item of `drivers` (its name already read and checked unique) into
/// definition.drivers. Throws InputError.
void read_driver(const NodeReader& item, const std::string& name, CaseDefinition& definition,
                 const ExpressionContext& expressions);

}  // namespace heavesim
