#pragma once
// Turbulent orifice flow with a smooth laminar region (docs/physics/compensators.md §8).
// The sharp-edged orifice law Q = C_d w x sqrt(2 dp / rho) has an infinite slope
// dQ/d(dp) at dp = 0, which would put an infinite entry in the Newton matrix. Below a
// transition pressure dp_t the real flow is laminar (linear in dp); one smooth
// function covers both:
//   Q = K x dp / (dp^2 + dp_t^2)^(1/4)
// -> K x sign(dp) sqrt(|dp|) for |dp| >> dp_t (turbulent), K x dp / sqrt(dp_t) near 0.
// K [m^3/s/Pa^0.5] is the flow coefficient of the fully open land (datasheet form
// K = Q_N / sqrt(dp_N): rated flow Q_N at the rated drop dp_N per land), x in [0, 1].
#include <cmath>

namespace heavesim {

/// Flow [m^3/s] through a land with coefficient K, opening x, pressure drop dp [Pa]
/// (positive: flow in its direction) and laminar transition pressure dp_t [Pa].
inline double orifice_flow(double coefficient, double opening, double pressure_drop, double transition_pressure) {
  return coefficient * opening * pressure_drop /
         std::sqrt(std::sqrt(pressure_drop * pressure_drop + transition_pressure * transition_pressure));
}

}  // namespace heavesim
