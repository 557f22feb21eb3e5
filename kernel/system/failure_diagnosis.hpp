#pragma once
// What a system can tell an integrator about a failed step, so that a numerical
// failure names where it happened (a joint, a body, a force element, a constraint row)
// and what the state looked like, not only a solver's return code. Every form an
// integrator sees (OdeSystem, DaeSystem, SecondOrderSystem) is one of these; the
// multibody forms answer from MultibodySystem (multibody_system.hpp). Called on the
// error path only: may allocate.
#include <string>

#include "kernel/spatial/types.hpp"

namespace heavesim {

class FailureDiagnosis {
 public:
  virtual ~FailureDiagnosis() = default;
  /// Names component `index` of the integrator's vector, e.g. "speed of joint 'pivot0'
  /// (body 'crank0')".
  virtual std::string describe_component(int index) const { return "component " + std::to_string(index); }
  /// What stands out in the integrator's vector y at time t [s] (a singular
  /// configuration, a non-finite value), or "" when nothing does.
  virtual std::string diagnose_state(double /*t*/, const VectorX& /*y*/) { return ""; }

  /// diagnose_state for an error message already being built: a diagnosis that fails
  /// itself says nothing rather than replace the error it explains.
  std::string state_note(double t, const VectorX& y) noexcept {
    try {
      return diagnose_state(t, y);
    } catch (...) {
      return "";
    }
  }
};

}  // namespace heavesim
