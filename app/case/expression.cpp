#include "app/case/expression.hpp"

#include <muParser.h>

#include <charconv>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>

#include <fmt/format.h>

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

namespace {

/// The names a case expression gives a meaning before any parameter, read from a parser
/// set up as every case expression's is, so that they follow muParser's own tables.
const std::set<std::string>& reserved_names() {
  static const std::set<std::string> names = [] {
    mu::Parser parser;
    define_case_functions(parser);
    std::set<std::string> reserved{"t"};  // the time of driver and joint-torque expressions
    for (const auto& function : parser.GetFunDef()) reserved.insert(function.first);
    for (const auto& constant : parser.GetConst()) reserved.insert(constant.first);
    return reserved;
  }();
  return names;
}

const std::string& valid_name_characters() {
  static const std::string characters = mu::Parser().ValidNameChars();
  return characters;
}

}  // namespace

std::string parameter_name_problem(const std::string& name) {
  if (name.empty()) return "an empty name";
  if (name.size() > static_cast<std::size_t>(mu::MaxLenIdentifier))
    return "a name of " + std::to_string(name.size()) + " characters";
  if (const std::size_t bad = name.find_first_not_of(valid_name_characters()); bad != std::string::npos) {
    const unsigned char byte = static_cast<unsigned char>(name[bad]);
    return byte >= 0x20 && byte < 0x7f ? "the character '" + std::string(1, name[bad]) + "'"
                                       : fmt::format("the byte 0x{:02X}", byte);
  }
  if (name[0] >= '0' && name[0] <= '9') return "a name that starts with a digit";
  if (name == "t") return "the time variable t of expressions";
  if (reserved_names().count(name)) return "a name that expressions already define";
  return "";
}

std::string parameter_name_expectation() {
  std::string reserved;
  for (const std::string& name : reserved_names()) reserved += (reserved.empty() ? "" : ", ") + name;
  return fmt::format("a name of ASCII letters, digits and _, not starting with a digit, at most {} characters, "
                     "and none of {}",
                     mu::MaxLenIdentifier, reserved);
}

ExpressionContext::ExpressionContext() : parser_(std::make_unique<mu::Parser>()) { define_case_functions(*parser_); }

ExpressionContext::~ExpressionContext() = default;

void ExpressionContext::define(const std::string& name, double value) {
  if (const std::string problem = parameter_name_problem(name); !problem.empty())
    throw std::invalid_argument("parameter name '" + name + "': " + problem);
  auto [it, inserted] = parameters_.insert_or_assign(name, value);
  if (!inserted) return;
  try {  // a mu::ParserError is no std::exception: past here it would end the program
    parser_->DefineVar(name, &it->second);
  } catch (const mu::Parser::exception_type& e) {
    parameters_.erase(it);
    throw std::invalid_argument(e.GetMsg());
  }
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
