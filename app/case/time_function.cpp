#include "app/case/time_function.hpp"

#include <muParser.h>

#include <cmath>
#include <stdexcept>

#include "app/case/expression.hpp"
#include "kernel/system/ode_system.hpp"

namespace heavesim {

TimeFunction::TimeFunction(std::string name, const std::string& position, const std::optional<std::string>& velocity,
                           const std::optional<std::string>& acceleration,
                           const std::map<std::string, double>& parameters, std::string owner)
    : name_(std::move(name)), owner_(std::move(owner)), parameters_(parameters) {
  auto make = [this](const std::string& text) {
    auto parser = std::make_unique<mu::Parser>();
    define_case_functions(*parser);
    try {  // a mu::ParserError is no std::exception: past here it would end the program
      parser->DefineVar("t", &time_);
      for (auto& [name, value] : parameters_) parser->DefineVar(name, &value);
      parser->SetExpr(text);
      parser->Eval();  // parses now, so that a bad expression is bad input, not a failure mid-run
    } catch (const mu::Parser::exception_type& e) {
      throw std::invalid_argument(e.GetMsg());
    }
    return parser;
  };
  position_ = make(position);
  if (velocity) velocity_ = make(*velocity);
  if (acceleration) acceleration_ = make(*acceleration);
}

TimeFunction::~TimeFunction() = default;

double TimeFunction::evaluate(mu::Parser& parser, double t) const {
  time_ = t;
  const double value = parser.Eval();
  if (!std::isfinite(value))
    throw NumericalError(t, owner_ + " '" + name_ + "': the expression '" + parser.GetExpr() + "' is not finite",
                         "check the " + owner_ + "'s expressions for a division by zero or a function outside its domain");
  return value;
}

bool TimeFunction::position_uses_time() const {
  // GetUsedVar parses once more, collecting the variables the expression reads, and
  // drops the compiled bytecode; the Eval after it compiles it again, here rather than
  // at the first evaluation of the run.
  const mu::varmap_type used = position_->GetUsedVar();
  position_->Eval();
  return used.count("t") > 0;
}

double TimeFunction::position(double t) const { return evaluate(*position_, t); }

DriverMotion TimeFunction::operator()(double t) const {
  DriverMotion motion;
  motion.position = position(t);
  if (velocity_ && acceleration_) {
    motion.velocity = evaluate(*velocity_, t);
    motion.acceleration = evaluate(*acceleration_, t);
    return motion;
  }
  // Fourth-order central differences (Fornberg 1988) on t +- h, t +- 2h.
  constexpr double h = difference_step;
  const double back2 = position(t - 2 * h), back1 = position(t - h);
  const double ahead1 = position(t + h), ahead2 = position(t + 2 * h);
  motion.velocity = velocity_ ? evaluate(*velocity_, t) : (back2 - 8 * back1 + 8 * ahead1 - ahead2) / (12 * h);
  motion.acceleration = acceleration_ ? evaluate(*acceleration_, t)
                                      : (-back2 + 16 * back1 - 30 * motion.position + 16 * ahead1 - ahead2) / (12 * h * h);
  return motion;
}

}  // namespace heavesim
