#include "app/case/expression.hpp"

#include <muParser.h>

#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace heavesim {
namespace {
double degrees_to_radians(double degrees) { return degrees * std::numbers::pi / 180.0; }
double radians_to_degrees(double radians) { return radians * 180.0 / std::numbers::pi; }
}  // namespace

void define_case_functions(mu::Parser& parser) {
  parser.DefineFun("deg", degrees_to_radians);
  parser.DefineFun("rad", radians_to_degrees);
  parser.DefineConst("pi", std::numbers::pi);
}

ExpressionContext::ExpressionContext() : parser_(std::make_unique<mu::Parser>()) { define_case_functions(*parser_); }

ExpressionContext::~ExpressionContext() = default;

void ExpressionContext::define(const std::string& name, double value) {
  auto [it, inserted] = parameters_.insert_or_assign(name, value);
  if (inserted) parser_->DefineVar(name, &it->second);
}

double ExpressionContext::evaluate(const std::string& text) const {
  // Plain numbers bypass the parser (exact, fast, and no locale issues).
  double value = 0.0;
  const char* begin = text.data();
  const char* end = begin + text.size();
  auto [ptr, error] = std::from_chars(begin, end, value);
  if (error == std::errc() && ptr == end) {
    if (!std::isfinite(value)) throw std::invalid_argument("not a finite number");
    return value;
  }
  try {
    parser_->SetExpr(text);
    value = parser_->Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw std::invalid_argument(e.GetMsg());
  }
  if (!std::isfinite(value)) throw std::invalid_argument("the expression does not evaluate to a finite number");
  return value;
}

}  // namespace heavesim
