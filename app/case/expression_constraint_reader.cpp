// Reads constraints[i] of type `expression` (docs/case-format.md, "constraints[i]").
#include "app/case/expression_constraint_reader.hpp"

#include <stdexcept>

#include "app/case/coordinate_expression.hpp"

namespace heavesim {
namespace {

const char* const constraint_expectation = "an expression of the variables' joint coordinates (and t) such as "
                                           "s - 0.2*sin(theta)";

/// The name of a joint of the tree at `reader`; another name is refused there with the
/// closest joint name as a did-you-mean (the joints are read before the constraints; the
/// model builder checks the joint's type).
std::string joint_name(const NodeReader& reader, const CaseDefinition& definition) {
  const std::string name = reader.text();
  std::vector<std::string> candidates;
  for (const JointDefinition& joint : definition.joints) {
    if (joint.name == name) return name;
    candidates.push_back(joint.name);
  }
  const std::string suggestion = closest_match(name, candidates);
  reader.fail("'" + name + "', which is not a joint of the tree",
              (suggestion.empty() ? "" : "'" + suggestion + "' (did you mean it?) or ") +
                  std::string("the name of a revolute, prismatic, cylindrical or universal joint"));
}

/// variables.<symbol>: a joint name (its only coordinate) or {joint: NAME, coordinate: K}.
ExpressionVariable read_variable(const NodeReader& reader, const std::string& symbol,
                                 const CaseDefinition& definition, const std::map<std::string, double>& parameters) {
  if (const std::string problem = parameter_name_problem(symbol); !problem.empty())
    reader.fail("variable name '" + symbol + "', " + problem, parameter_name_expectation());
  if (parameters.count(symbol))
    reader.fail("variable name '" + symbol + "', already a case parameter", "a name no parameter uses");
  ExpressionVariable variable;
  variable.name = symbol;
  if (reader.node().is_map()) {
    reader.expect_section("expression_variable");
    variable.joint = joint_name(reader["joint"], definition);
    if (auto coordinate = reader.optional("coordinate")) variable.coordinate = static_cast<int>(coordinate->integer());
  } else {
    variable.joint = joint_name(reader, definition);
  }
  return variable;
}

}  // namespace

void read_expression_constraint(const NodeReader& item, const std::string& name, CaseDefinition& definition,
                                const ExpressionContext& expressions) {
  item.expect_section("expression_constraint");
  ExpressionConstraintDefinition def;
  def.name = name;
  const NodeReader variables = item["variables"];
  if (!variables.node().is_map()) variables.fail("a map of symbol: joint (or symbol: {joint, coordinate})");
  std::vector<std::string> symbols;
  for (const CaseNode::Entry& entry : variables.node().entries) {
    def.variables.push_back(read_variable(variables[entry.key], entry.key, definition, expressions.parameters()));
    symbols.push_back(entry.key);
  }
  const NodeReader text = item["expression"];
  if (!text.node().is_scalar()) text.fail(constraint_expectation);
  std::shared_ptr<const CoordinateExpression> function;
  try {
    // muParser's message names an unknown symbol and the column of a syntax error.
    function = std::make_shared<const CoordinateExpression>(text.node().scalar, symbols, expressions.parameters());
  } catch (const std::invalid_argument& e) {
    text.fail(text.node().describe() + " (" + e.what() + ")", constraint_expectation);
  }
  // A constraint of t alone would prescribe nothing about the mechanism (and have a
  // zero Jacobian row); a declared coordinate it does not read is a typo somewhere.
  if (symbols.empty())
    text.fail(text.node().describe() + ", which reads no joint coordinate (variables is empty)",
              "an expression of at least one joint coordinate named in variables");
  for (std::size_t k = 0; k < symbols.size(); ++k)
    if (!function->reads(static_cast<int>(k)))
      variables[symbols[k]].fail("'" + symbols[k] + "', which the expression " + text.node().describe() +
                                     " does not read",
                                 "only the coordinates the expression reads");
  def.function = function;
  definition.expression_constraints.push_back(std::move(def));
}

}  // namespace heavesim
