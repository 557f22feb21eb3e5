#pragma once
// Start-up ramp R(t) that multiplies wave elevation and wave forces, so a run does not
// begin with an impulsive load.
#include <cmath>

namespace heavesim::hydro {

enum class RampKind { none, cosine, hyperbolic_tangent };

struct Ramp {
  RampKind kind = RampKind::none;
  double duration = 0.0;  // t_r [s]

  /// cosine (WEC-Sim): R = (1 - cos(pi t / t_r)) / 2 for t < t_r, 1 after (C1 at t_r);
  /// hyperbolic_tangent: R = tanh(3 t / t_r) (0.995 at t_r, never exactly 1).
  double operator()(double t) const {
    if (kind == RampKind::none || duration <= 0.0) return 1.0;
    if (t <= 0.0) return 0.0;
    if (kind == RampKind::cosine) return t >= duration ? 1.0 : 0.5 * (1.0 - std::cos(M_PI * t / duration));
    return std::tanh(3.0 * t / duration);
  }
};

}  // namespace heavesim::hydro
