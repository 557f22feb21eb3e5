#pragma once
// Numbers in case files may be expressions (muParser): "deg(90)", "pi/2",
// "0.5 * L" with user parameters, and "8 + 3*sin(t)" for drivers.
#include <map>
#include <memory>
#include <string>

namespace mu {
class Parser;
class ParserError;
}

namespace heavesim {

/// Adds what every case expression may use: the functions of case_functions.hpp (which
/// replace muParser's built-ins of the same names, so that each has a derivative rule),
/// the helpers step, step5, ramp, smoothstep, deg(x), rad(x) and the constant pi.
void define_case_functions(mu::Parser& parser);

/// muParser's message for an expression it refused, with the position (muParser's
/// 0-based character index, at most the expression's length) where the message lacks it
/// ("Missing parenthesis at position 11" for "8 + 3*sin(t").
std::string parser_error_text(const mu::ParserError& error, const std::string& expression);

/// Why `name` cannot name a case parameter ("" when it can): it must be a variable name
/// by muParser's rules (its name characters, not starting with a digit, its length
/// limit) and not a name that expressions already give a meaning: muParser's built-in
/// functions and constants (sin, ..., _pi, _e), ours (deg, rad, step, ..., pi), and the time t.
std::string parameter_name_problem(const std::string& name);
/// What a parameter name must be, for messages (lists the reserved names).
std::string parameter_name_expectation();

class ExpressionContext {
 public:
  ExpressionContext();
  ~ExpressionContext();
  ExpressionContext(const ExpressionContext&) = delete;
  ExpressionContext& operator=(const ExpressionContext&) = delete;

  /// Defines (or redefines) a named parameter usable in later expressions; throws
  /// std::invalid_argument for a name parameter_name_problem rejects.
  void define(const std::string& name, double value);
  bool defines(const std::string& name) const { return parameters_.count(name) > 0; }

  /// Value of a number or expression; throws std::invalid_argument with muParser's reason.
  double evaluate(const std::string& text) const;

  /// The named parameters defined so far.
  const std::map<std::string, double>& parameters() const { return parameters_; }

 private:
  std::unique_ptr<mu::Parser> parser_;
  std::map<std::string, double> parameters_;  // node-based: addresses stay valid for muParser
};

}  // namespace heavesim
