#pragma once
// Closed forms of a polytropic gas spring for the compensator checks, written from
// the textbook (p V^n = const, ideal gas) independently of control/.
#include <cmath>

namespace heavesim::oracle {

/// Work [J] the gas does on a piston of area A [m^2] against the atmosphere p_atm [Pa]
/// when the stroke goes from 0 to s [m], V = V0 + A s, p V^n = p0 V0^n:
///   W = integral_0^s (p - p_atm) A ds' = (p0 V0 - p V) / (n - 1) - p_atm (V - V0).
inline double gas_spring_work(double p0, double V0, double A, double n, double p_atm, double s) {
  const double V = V0 + A * s;
  const double p = p0 * std::pow(V0 / V, n);
  return (p0 * V0 - p * V) / (n - 1.0) - p_atm * (V - V0);
}

}  // namespace heavesim::oracle
