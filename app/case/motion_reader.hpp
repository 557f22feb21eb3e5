#pragma once
// Prescribed motions f(t) in a case: the motion keys of a driver (position, velocity,
// acceleration; or table) read into a TimeFunction, and the checks of every expression
// of t over the run before it starts (finite with its derivatives everywhere; given
// derivatives that agree with the exact ones; tables that cover the run).
#include <memory>
#include <optional>
#include <string>

#include "app/case/case_definition.hpp"
#include "app/case/expression.hpp"
#include "app/case/node_reader.hpp"
#include "app/case/time_function.hpp"

namespace heavesim {

/// The motion of the item (a driver): its `position` expression of t and the optional
/// `velocity` and `acceleration`, or its `table` (a CSV file relative to the file that
/// holds the key). Throws InputError at the key that does not parse or read.
std::shared_ptr<const TimeFunction> read_motion(const NodeReader& item, const std::string& name,
                                                const ExpressionContext& expressions);

/// The expression of t at `key` (a scalar) with no derivatives: a joint torque, a load
/// component. Parsed here, once, so that a bad expression is bad input at its key, not a
/// failure mid-run. `owner` names what it belongs to in diagnoses ("joint torque").
std::shared_ptr<const TimeFunction> read_time_expression(const NodeReader& key, const std::string& name,
                                                         const ExpressionContext& expressions,
                                                         const std::string& owner, const std::string& expected);

/// Every expression of t in the case -- each driver's motion, each joint torque, each
/// body load component --
/// evaluated over the run; a driver's given derivatives compared with the exact ones.
/// `drivers` is the case's drivers section (the items in definition.drivers' order).
void check_motions_over_run(const CaseDefinition& definition, const ExpressionContext& expressions,
                            const std::optional<NodeReader>& drivers);

}  // namespace heavesim
