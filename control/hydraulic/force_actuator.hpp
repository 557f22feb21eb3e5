#pragma once
// The simpler actuator for early design (docs/physics/compensators.md §7): the force follows
// the saturated command through a first-order lag, optionally rate limited,
//   dF/dt = clamp((u_sat - F) / tau_a, -r_max, r_max),   |u_sat| <= F_max.
// With tau_a = 0 the force is u_sat itself (no state, no rate limit).
#include <algorithm>
#include <limits>

namespace heavesim {

struct ForceActuatorParameters {
  double time_constant = 0.1;  // tau_a [s], >= 0
  double max_force = 3.9e5;    // F_max [N], > 0 (0.15 W_c for the default rig)
  double max_rate = std::numeric_limits<double>::infinity();  // r_max [N/s], > 0
};

/// dF/dt [N/s] for actuator force F [N] and saturated command u_sat [N].
inline double force_actuator_rate(const ForceActuatorParameters& actuator, double force, double command) {
  return std::clamp((command - force) / actuator.time_constant, -actuator.max_rate, actuator.max_rate);
}

}  // namespace heavesim
