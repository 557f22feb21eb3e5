#include "app/case/time_function.hpp"

#include <cmath>
#include <limits>

#include "app/case/motion_table.hpp"
#include "app/case/taylor_evaluation.hpp"
#include "kernel/math/numerical_error.hpp"

namespace heavesim {

TimeFunction::TimeFunction(std::string name, const std::string& position, const std::optional<std::string>& velocity,
                           const std::optional<std::string>& acceleration,
                           const std::map<std::string, double>& parameters, std::string owner)
    : name_(std::move(name)), owner_(std::move(owner)) {
  auto make = [&](const std::string& text) { return std::make_unique<DifferentiableExpression>(text, std::vector<std::string>{"t"}, parameters); };
  position_ = make(position);
  if (velocity) velocity_ = make(*velocity);
  if (acceleration) acceleration_ = make(*acceleration);
}

TimeFunction::TimeFunction(std::string name, std::shared_ptr<const MotionTable> table, std::string owner)
    : name_(std::move(name)), owner_(std::move(owner)), table_(std::move(table)) {}

TimeFunction::~TimeFunction() = default;

std::pair<double, double> TimeFunction::time_range() const {
  if (table_) return {table_->start_time(), table_->end_time()};
  return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
}

void TimeFunction::not_finite(double t, const DifferentiableExpression& expression, const char* what) const {
  throw NumericalError(t, owner_ + " '" + name_ + "': the expression '" + expression.text() + "'" + what + " is not finite",
                       "check the " + owner_ + "'s expressions for a division by zero or a function outside its domain");
}

bool TimeFunction::position_uses_time() const { return table_ || position_->reads(0); }

double TimeFunction::position(double t) const {
  if (table_) return (*table_)(t).position;
  const double value = position_->value(&t);
  if (!std::isfinite(value)) not_finite(t, *position_, "");
  return value;
}

DriverMotion TimeFunction::operator()(double t) const {
  if (table_) return (*table_)(t);  // finite: a spline through finite samples
  const Taylor2 time = Taylor2::variable(t);
  const Taylor2 exact = position_->evaluate(&time);
  if (!std::isfinite(exact.value)) not_finite(t, *position_, "");
  DriverMotion motion{exact.value, exact.first, exact.second};
  if (velocity_) {
    motion.velocity = velocity_->value(&t);
    if (!std::isfinite(motion.velocity)) not_finite(t, *velocity_, "");
  } else if (!std::isfinite(motion.velocity)) {
    not_finite(t, *position_, ", differentiated once,");
  }
  if (acceleration_) {
    motion.acceleration = acceleration_->value(&t);
    if (!std::isfinite(motion.acceleration)) not_finite(t, *acceleration_, "");
  } else if (!std::isfinite(motion.acceleration)) {
    not_finite(t, *position_, ", differentiated twice,");
  }
  return motion;
}

}  // namespace heavesim
