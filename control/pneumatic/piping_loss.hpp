#pragma once
// Pressure loss in the oil piping between the compensator cylinders and the
// accumulator (docs/physics/compensators.md §3): laminar Hagen-Poiseuille plus a turbulent
// loss coefficient,
//   dp(Q) = R_l Q + K_t Q |Q|,   R_l = 128 mu L / (pi d^4),   K_t = zeta rho / (2 a^2),
// with a = pi d^2 / 4 the pipe bore area. dp is the drop in the direction of the flow
// Q [m^3/s]; it is smooth (C1) through Q = 0.
#include <numbers>

namespace heavesim {

struct PipingLoss {
  double laminar_resistance = 0.0;     // R_l [Pa s/m^3]
  double turbulent_coefficient = 0.0;  // K_t [Pa s^2/m^6]
};

/// From the pipe: length L [m], bore d [m], oil dynamic viscosity mu [Pa s], oil
/// density rho [kg/m^3], total loss coefficient zeta [-] (bends, valves, f L / d).
inline PipingLoss piping_loss_from_pipe(double length, double bore, double viscosity, double density,
                                        double loss_coefficient) {
  const double area = std::numbers::pi * bore * bore / 4.0;
  return {128.0 * viscosity * length / (std::numbers::pi * bore * bore * bore * bore),
          loss_coefficient * density / (2.0 * area * area)};
}

/// Pressure drop [Pa] along the flow Q [m^3/s].
inline double piping_pressure_drop(const PipingLoss& loss, double flow) {
  return loss.laminar_resistance * flow + loss.turbulent_coefficient * flow * (flow < 0.0 ? -flow : flow);
}

}  // namespace heavesim
