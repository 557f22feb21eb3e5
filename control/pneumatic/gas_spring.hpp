#pragma once
// Closed forms of a polytropic gas spring (docs/physics/compensators.md
// §2). A fixed mass of ideal gas in the accumulator and air pressure vessels, volume
// V [m^3], absolute pressure p [Pa], temperature T [K]; a polytropic change keeps
// p V^n constant (n = 1 isothermal ... 1.4 adiabatic for a diatomic gas).
#include <cmath>

namespace heavesim {

/// p = p0 (V0 / V)^n.
inline double polytropic_pressure(double p0, double V0, double V, double n) { return p0 * std::pow(V0 / V, n); }

/// T = T0 (V0 / V)^(n - 1) (ideal gas: T proportional to p V).
inline double polytropic_temperature(double T0, double V0, double V, double n) {
  return T0 * std::pow(V0 / V, n - 1.0);
}

/// Local stiffness of the spring on a piston of area A [m^2] whose stroke changes the
/// volume by A per metre: k = dF/ds = n p A^2 / V [N/m].
inline double polytropic_stiffness(double p, double V, double A, double n) { return n * p * A * A / V; }

/// Work [J] done BY the gas from state 1 to state 2 along p V^n = const:
///   W = integral p dV = (p1 V1 - p2 V2) / (n - 1), and p1 V1 ln(V2 / V1) for n = 1.
inline double polytropic_work(double p1, double V1, double p2, double V2, double n) {
  if (std::abs(n - 1.0) < 1e-12) return p1 * V1 * std::log(V2 / V1);
  return (p1 * V1 - p2 * V2) / (n - 1.0);
}

}  // namespace heavesim
