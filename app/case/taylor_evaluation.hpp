#pragma once
// A case expression of named variables (t; a constraint's coordinates) evaluated with
// exact first and second derivatives: muParser parses it (its syntax, its messages with
// the column), and its bytecode -- the expression in reverse Polish notation
// (mu::ParserBase::GetByteCode(), muParserBytecode.h) -- is evaluated again with
// Taylor2 scalars (taylor_scalar.hpp) in place of doubles. No finite differences.
//
// Evaluation allocates nothing (its stack is sized once, at construction) and is not
// thread-safe (the stack is shared by calls, as muParser's own is).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <muParserBytecode.h>

#include "app/case/taylor_scalar.hpp"

namespace mu {
class Parser;
}

namespace heavesim {

class DifferentiableExpression {
 public:
  /// Parses `text` with the case's functions (define_case_functions), the free
  /// `variables` (in this order in the evaluations below) and the case's `parameters`
  /// (constants here). Throws std::invalid_argument with muParser's message (which
  /// gives the column of a syntax error), or for what has no derivative: an
  /// assignment, several comma-separated results.
  DifferentiableExpression(const std::string& text, const std::vector<std::string>& variables,
                           const std::map<std::string, double>& parameters);
  ~DifferentiableExpression();
  DifferentiableExpression(const DifferentiableExpression&) = delete;
  DifferentiableExpression& operator=(const DifferentiableExpression&) = delete;

  /// The value at `variables` (one per variable name), by muParser.
  double value(const double* variables) const;
  /// The value and its first two derivatives along the path the variables' Taylor
  /// scalars describe: the variable k at s is variables[k].value + s variables[k].first
  /// + s^2/2 variables[k].second.
  Taylor2 evaluate(const Taylor2* variables) const;

  /// Whether the expression reads the variable of that index.
  bool reads(int variable) const { return reads_[variable]; }
  const std::string& text() const { return text_; }

 private:
  Taylor2 operand(const mu::SToken& token, const Taylor2* variables) const;

  std::string text_;
  std::unique_ptr<mu::Parser> parser_;
  std::map<std::string, double> parameters_;  // node-based: addresses stay valid for muParser
  std::unique_ptr<double[]> variable_values_;   // the addresses muParser reads the variables at
  int variable_count_ = 0;
  std::vector<bool> reads_;
  std::vector<mu::SToken> bytecode_;        // a copy of the parser's, ending in cmEND
  mutable std::vector<Taylor2> stack_;      // sized once: muParser's maximum stack size
};

}  // namespace heavesim
