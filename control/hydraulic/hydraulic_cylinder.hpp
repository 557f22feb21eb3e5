#pragma once
// A double-acting hydraulic cylinder with compressible oil (docs/physics/compensators.md §9).
// Chamber A grows when the stroke s grows (it pushes the moving side along +axis),
// chamber B shrinks:
//   V_A = V_A0 + A_A s,   V_B = V_B0 - A_B s
//   dp_A/dt = beta / V_A (Q_A - A_A ds/dt - C_i (p_A - p_B) - C_e (p_A - p_T))
//   dp_B/dt = beta / V_B (Q_B + A_B ds/dt + C_i (p_A - p_B) - C_e (p_B - p_T))
//   F = p_A A_A - p_B A_B - p_atm (A_A - A_B) + F_friction(ds/dt)
// with Q_A, Q_B the valve flows into the chambers, C_i the internal (cross-piston) and
// C_e the external leakage coefficients. The blocked cylinder (Q = 0, no leakage) is a
// spring of stiffness beta (A_A^2 / V_A + A_B^2 / V_B): with a mass m on it,
//   omega_h = sqrt(beta (A_A^2 / V_A + A_B^2 / V_B) / m).
#include "control/stroke/seal_friction.hpp"

namespace heavesim {

struct HydraulicCylinderParameters {
  double area_a = 0.03;              // A_A [m^2], piston side
  double area_b = 0.015;             // A_B [m^2], annulus side
  double volume_a = 0.15;            // V_A0 [m^3] at s = 0, hoses and dead volume included
  double volume_b = 0.08;            // V_B0 [m^3] at s = 0
  double bulk_modulus = 1.0e9;       // beta [Pa], effective (oil, hoses, entrained air)
  double internal_leakage = 0.0;     // C_i [m^3/(s Pa)]
  double external_leakage = 0.0;     // C_e [m^3/(s Pa)]
  double atmospheric_pressure = 101325.0;  // Pa, on the rod cross-section A_A - A_B
  SealFriction friction;
};

struct ChamberVolumes {
  double a, b;  // m^3
};
inline ChamberVolumes chamber_volumes(const HydraulicCylinderParameters& c, double stroke) {
  return {c.volume_a + c.area_a * stroke, c.volume_b - c.area_b * stroke};
}

/// dp_A/dt and dp_B/dt [Pa/s].
struct ChamberPressureRates {
  double a, b;
};
inline ChamberPressureRates chamber_pressure_rates(const HydraulicCylinderParameters& c, const ChamberVolumes& volumes,
                                                   double flow_into_a, double flow_into_b, double pressure_a,
                                                   double pressure_b, double tank_pressure, double stroke_rate) {
  const double internal = c.internal_leakage * (pressure_a - pressure_b);
  return {c.bulk_modulus / volumes.a *
              (flow_into_a - c.area_a * stroke_rate - internal - c.external_leakage * (pressure_a - tank_pressure)),
          c.bulk_modulus / volumes.b *
              (flow_into_b + c.area_b * stroke_rate + internal - c.external_leakage * (pressure_b - tank_pressure))};
}

/// Pressure force [N] of the cylinder on the moving side, positive extends (no friction).
inline double cylinder_pressure_force(const HydraulicCylinderParameters& c, double pressure_a, double pressure_b) {
  return pressure_a * c.area_a - pressure_b * c.area_b - c.atmospheric_pressure * (c.area_a - c.area_b);
}

}  // namespace heavesim
