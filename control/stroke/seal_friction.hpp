#pragma once
// Seal friction of a cylinder: smoothed Coulomb plus viscous (docs/physics/compensators.md §4;
// the tanh form MBARI uses on its motor),
//   F_f(v) = -(F_c tanh(v / v_s) + c_v v)   [N], opposing the stroke rate v [m/s].
// The tanh keeps the force smooth through v = 0, so error-controlled integrators do not
// stall on a sign switch; |F_f| is within 1 % of F_c once |v| > 2.65 v_s.
#include <cmath>

namespace heavesim {

struct SealFriction {
  double coulomb_force = 0.0;      // F_c [N], >= 0
  double viscous_damping = 0.0;    // c_v [N s/m], >= 0
  double smoothing_speed = 0.01;   // v_s [m/s], > 0
};

/// The friction force [N] on the moving side for stroke rate v [m/s].
inline double seal_friction_force(const SealFriction& friction, double rate) {
  return -(friction.coulomb_force * std::tanh(rate / friction.smoothing_speed) + friction.viscous_damping * rate);
}

}  // namespace heavesim
