#pragma once
// A prescribed motion written in the case as a muParser expression of time t [s] and
// the case's parameters ("8 + 3*sin(t)"), with its first two time derivatives.
//
// The derivatives are exact when the case gives them as expressions (`velocity`,
// `acceleration`); otherwise they come from fourth-order central differences with
// step h = 1e-3 s (Fornberg's stencils): truncation h^4 f^(5)/30 and h^4 f^(6)/90,
// round-off about 1e-13 |f| / h and 1e-16 |f| / h^2 -- so about 1e-10 relative for
// motions slower than ~10 rad/s. Give the derivatives where accuracy matters.
// A value that is not finite during a run is a NumericalError naming the driver.
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "kernel/model/constraint.hpp"

namespace mu {
class Parser;
}

namespace heavesim {

class TimeFunction {
 public:
  /// Throws std::invalid_argument (with muParser's reason) for an expression that does
  /// not parse; `parameters` are the case's named values, copied. `owner` names what the
  /// function belongs to in diagnoses ("driver", "joint torque").
  TimeFunction(std::string name, const std::string& position, const std::optional<std::string>& velocity,
               const std::optional<std::string>& acceleration, const std::map<std::string, double>& parameters,
               std::string owner = "driver");
  ~TimeFunction();
  TimeFunction(const TimeFunction&) = delete;
  TimeFunction& operator=(const TimeFunction&) = delete;

  /// Step of the central differences that stand in for missing derivatives [s].
  static constexpr double difference_step = 1e-3;

  DriverMotion operator()(double t) const;

  /// Position at t, with no derivatives [m or rad].
  double position(double t) const;
  /// Whether the position expression reads t (a constant needs no time dependence).
  bool position_uses_time() const;

 private:
  double evaluate(mu::Parser& parser, double t) const;

  std::string name_;                          // the driver's, for diagnoses
  std::string owner_;                         // "driver", ..., for diagnoses
  std::map<std::string, double> parameters_;  // node-based: addresses stay valid for muParser
  mutable double time_ = 0.0;                 // the variable t every parser reads
  std::unique_ptr<mu::Parser> position_, velocity_, acceleration_;
};

}  // namespace heavesim
