#include "app/case/expression.hpp"

#include "app/case/case_functions.hpp"

#include <muParser.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>

#include <fmt/format.h>

namespace heavesim {
double call_case_function_1(void* entry, double a) {
  return apply_case_function(static_cast<const CaseFunctionEntry*>(entry)->function, &a, 1);
}
double call_case_function_2(void* entry, double a, double b) {
  const double args[] = {a, b};
  return apply_case_function(static_cast<const CaseFunctionEntry*>(entry)->function, args, 2);
}
double call_case_function_3(void* entry, double a, double b, double c) {
  const double args[] = {a, b, c};
  return apply_case_function(static_cast<const CaseFunctionEntry*>(entry)->function, args, 3);
}
double call_case_function_5(void* entry, double a, double b, double c, double d, double e) {
  const double args[] = {a, b, c, d, e};
  return apply_case_function(static_cast<const CaseFunctionEntry*>(entry)->function, args, 5);
}
double call_case_function_n(void* entry, const double* args, int count) {
  if (count < 1) throw mu::ParserError("too few arguments");
  return apply_case_function(static_cast<const CaseFunctionEntry*>(entry)->function, args, count);
}
double case_unary_minus(double x) { return -x; }
double case_unary_plus(double x) { return x; }

void define_case_functions(mu::Parser& parser) {
  // Redefining muParser's built-ins under the same names replaces them (its function
  // table is a map by name): every function is then one of case_functions.hpp.
  for (const CaseFunctionEntry& entry : case_function_table) {
    void* data = const_cast<CaseFunctionEntry*>(&entry);  // muParser's user data is void*; never written
    switch (entry.arguments) {
      case 1: parser.DefineFunUserData(entry.name, call_case_function_1, data); break;
      case 2: parser.DefineFunUserData(entry.name, call_case_function_2, data); break;
      case 3: parser.DefineFunUserData(entry.name, call_case_function_3, data); break;
      case 5: parser.DefineFunUserData(entry.name, call_case_function_5, data); break;
      default: parser.DefineFunUserData(entry.name, call_case_function_n, data); break;
    }
  }
  parser.DefineInfixOprt("-", case_unary_minus);
  parser.DefineInfixOprt("+", case_unary_plus);
  parser.DefineConst("pi", std::numbers::pi);
}

std::string parser_error_text(const mu::ParserError& error, const std::string& expression) {
  std::string message = error.GetMsg();
  const int position = error.GetPos();
  if (position >= 0 && message.find("position") == std::string::npos)
    message += fmt::format(" at position {}", std::min<std::size_t>(position, expression.size()));
  return message;
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
    throw std::invalid_argument(parser_error_text(e, text));
  }
  if (!std::isfinite(value)) throw std::invalid_argument("the expression does not evaluate to a finite number");
  return value;
}

}  // namespace heavesim
