#pragma once
// A prescribed motion written in the case as a muParser expression of time t [s] and
// the case's parameters ("8 + 3*sin(t)"), with its first two time derivatives.
//
// The derivatives are exact: the expression's bytecode is evaluated with second-order
// Taylor scalars in t (taylor_evaluation.hpp), never by finite differences. When the
// case gives them as expressions (`velocity`, `acceleration`) those are used; the case
// reader checks them against the exact ones (motion_reader.hpp).
// Or a tabulated motion (motion_table.hpp): a spline through samples, derivatives
// exact for the spline.
// A value or derivative that is not finite during a run is a NumericalError naming
// the owner.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "kernel/model/constraint.hpp"

namespace heavesim {

class DifferentiableExpression;
class MotionTable;

class TimeFunction {
 public:
  /// Throws std::invalid_argument (with muParser's reason) for an expression that does
  /// not parse; `parameters` are the case's named values, copied. `owner` names what the
  /// function belongs to in diagnoses ("driver", "joint torque").
  TimeFunction(std::string name, const std::string& position, const std::optional<std::string>& velocity,
               const std::optional<std::string>& acceleration, const std::map<std::string, double>& parameters,
               std::string owner = "driver");
  /// A tabulated motion.
  TimeFunction(std::string name, std::shared_ptr<const MotionTable> table, std::string owner = "driver");
  ~TimeFunction();
  TimeFunction(const TimeFunction&) = delete;
  TimeFunction& operator=(const TimeFunction&) = delete;

  /// f(t), f'(t), f''(t) [m, m/s, m/s^2 or rad, rad/s, rad/s^2].
  DriverMotion operator()(double t) const;

  /// Position at t, with no derivatives [m or rad].
  double position(double t) const;
  /// Whether the position expression reads t (a constant needs no time dependence).
  bool position_uses_time() const;
  /// The times it is defined over [s]: a table's first and last; every time for an expression.
  std::pair<double, double> time_range() const;

 private:
  [[noreturn]] void not_finite(double t, const DifferentiableExpression& expression, const char* what) const;

  std::string name_;   // the driver's, for diagnoses
  std::string owner_;  // "driver", ..., for diagnoses
  std::unique_ptr<DifferentiableExpression> position_, velocity_, acceleration_;  // null for a table
  std::shared_ptr<const MotionTable> table_;                                      // null for an expression
};

}  // namespace heavesim
