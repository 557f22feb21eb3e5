#pragma once
// What a system can tell an integrator about a failed step, so that a numerical
// failure names where it happened (a joint, a body, a force element, a constraint row)
// and what caused it, not only a solver's return code. Every form an integrator sees
// (OdeSystem, DaeSystem, SecondOrderSystem) is one of these; the multibody forms answer
// from MultibodySystem (multibody_system.hpp, fastest_mode.hpp). Called on the error
// path only: may allocate.
#include <complex>
#include <cstdio>
#include <string>

#include "kernel/math/numerical_error.hpp"
#include "kernel/spatial/types.hpp"

namespace heavesim {

/// What stands out in a state: a non-finite value, loops at a singular configuration,
/// a driver pulling a loop where it cannot close. `suggestion` is set when the cause
/// dictates the remedy whatever the integrator (a driver beyond a loop's reach); when
/// empty, the integrator suggests what fits it.
struct StateDiagnosis {
  std::string what;
  std::string suggestion;
  bool empty() const { return what.empty(); }
  /// The failure at t described by `failure`, with this diagnosis appended when there is
  /// one; its suggestion when it has one, else `fallback` (the remedy the caller knows).
  NumericalError explain(double t, std::string failure, const std::string& fallback) const {
    if (!empty()) failure += "; " + what;
    return NumericalError(t, failure, !suggestion.empty() ? suggestion : fallback);
  }
};

/// The fastest mode of the equations linearized at a state: what limits an explicit
/// method's step (its stability limit is a few times 1/|eigenvalue|) and what an
/// implicit one must resolve if the mode is excited and undamped.
struct FastestMode {
  std::complex<double> eigenvalue;  // 1/s; 0 when none was found
  std::string where;    // "body 'cart2' (1e-06 kg, joint 'slide2')", or an element's state
  std::string element;  // what makes it fast, as the user named it: "the spring of joint 'slide2'"; "" if none stands out
  bool found() const { return std::abs(eigenvalue) > 0.0; }
  /// "the fastest mode (omega = 6.67e+04 rad/s), which moves body 'load' (2.9e+05 kg,
  /// joint 'compensator') against force element 'strut'"
  std::string description() const;
};

class FailureDiagnosis {
 public:
  virtual ~FailureDiagnosis() = default;
  /// Names component `index` of the integrator's vector, e.g. "speed of joint 'pivot0'
  /// (body 'crank0')".
  virtual std::string describe_component(int index) const { return "component " + std::to_string(index); }
  /// What stands out in the integrator's vector y at time t [s]; empty when nothing does.
  virtual StateDiagnosis diagnose_state(double /*t*/, const VectorX& /*y*/) { return {}; }
  /// The fastest mode at (t, y) of the ODE state y; none by default.
  virtual FastestMode fastest_mode(double /*t*/, const VectorX& /*y*/) { return {}; }

  /// diagnose_state for an error message already being built: a diagnosis that fails
  /// itself says nothing rather than replace the error it explains.
  StateDiagnosis state_note(double t, const VectorX& y) noexcept {
    try {
      return diagnose_state(t, y);
    } catch (...) {
      return {};
    }
  }
  /// fastest_mode on the error path: none when the state cannot be linearized.
  FastestMode fastest_mode_note(double t, const VectorX& y) noexcept {
    try {
      return y.allFinite() ? fastest_mode(t, y) : FastestMode{};
    } catch (...) {
      return {};
    }
  }
};

inline std::string FastestMode::description() const {
  // An oscillation is named by its frequency, a fast decay (a stiff damper, a thermal
  // time constant) by its rate.
  char rate[64];
  if (std::abs(eigenvalue.imag()) >= std::abs(eigenvalue.real()))
    std::snprintf(rate, sizeof rate, "omega = %.3g rad/s", std::abs(eigenvalue.imag()));
  else
    std::snprintf(rate, sizeof rate, "decay rate %.3g 1/s", std::abs(eigenvalue.real()));
  std::string text = std::string("the fastest mode (") + rate + "), which moves " + where;
  text += element.empty() ? " (no force element stands out: inertial or constraint forces)" : " against " + element;
  return text;
}

}  // namespace heavesim
