#pragma once
// drivers[i] of a case: prescribed motions as constraints (docs/case-format.md).
#include <optional>
#include <string>

#include "app/case/case_definition.hpp"
#include "app/case/expression.hpp"
#include "app/case/node_reader.hpp"

namespace heavesim {

/// Reads one item of `drivers` (its name already read and checked unique) into
/// definition.drivers. Throws InputError.
void read_driver(const NodeReader& item, const std::string& name, CaseDefinition& definition,
                 const ExpressionContext& expressions);

/// A distance driver's f(t) must stay > 0: evaluated at every output time of the run
/// (where a kinematic analysis solves and a run records). `drivers` is the case's
/// drivers section (its items in definition.drivers' order). Throws InputError at the
/// driver's position.
void check_distance_drivers_over_run(const CaseDefinition& definition, const std::optional<NodeReader>& drivers);

}  // namespace heavesim
