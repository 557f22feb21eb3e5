#pragma once
// A 4/3 servo valve (docs/physics/compensators.md §8) with second-order spool dynamics
//   d^2 x/dt^2 = w_v^2 (u - x) - 2 zeta_v w_v dx/dt
// (x: spool opening, -1 ... 1; u: the saturated command) and orifice flows through
// four lands: for x > 0 supply P -> chamber A and chamber B -> tank T, for x < 0
// P -> B and A -> T. An underlap x_u opens every land by x_u at null:
//   P->A and B->T open max(x_u + x, 0),  P->B and A->T open max(x_u - x, 0)
// (x_u = 0: critically centred). The resulting null leakage gives the valve a
// flow-pressure coefficient K_c0 = dQ/dp > 0 at null, which is what damps the
// cylinder's hydraulic resonance; a critically centred valve leaves it undamped
// (Merritt, Hydraulic Control Systems, 1967, §5.2).
#include <algorithm>
#include <cmath>

#include "control/hydraulic/orifice.hpp"

namespace heavesim {

struct ServoValveParameters {
  double rated_flow = 0.02;             // Q_N [m^3/s] at full opening and the rated drop
  double rated_pressure_drop = 3.5e6;   // dp_N [Pa] per land (35 bar)
  double natural_frequency = 2 * 3.141592653589793 * 30.0;  // w_v [rad/s] (30 Hz)
  double damping = 0.7;                 // zeta_v [-]
  double transition_pressure = 1e5;     // dp_t [Pa], laminar region of the orifice law
  double underlap = 0.0;                // x_u [-], opening of every land at null
  double flow_coefficient() const { return rated_flow / std::sqrt(rated_pressure_drop); }  // K
};

/// Supply and return: constant-pressure power unit and tank (absolute pressures).
struct HydraulicSupply {
  double supply_pressure = 21e6;  // p_S [Pa]
  double tank_pressure = 2e5;     // p_T [Pa]
};

/// Flows through the valve at spool opening x, chamber pressures p_a, p_b [Pa].
struct ValveFlows {
  double into_a;  // m^3/s, valve -> chamber A
  double into_b;  // m^3/s, valve -> chamber B
  double supply;  // m^3/s drawn from the supply (>= 0 while p_S exceeds the chamber pressures)
};

inline ValveFlows valve_flows(const ServoValveParameters& valve, const HydraulicSupply& supply, double opening,
                              double pressure_a, double pressure_b) {
  const double K = valve.flow_coefficient(), dp_t = valve.transition_pressure;
  const double open_pa = std::max(valve.underlap + opening, 0.0);  // P -> A, B -> T
  const double open_pb = std::max(valve.underlap - opening, 0.0);  // P -> B, A -> T
  const double p_s = supply.supply_pressure, p_t = supply.tank_pressure;
  const double supply_to_a = orifice_flow(K, open_pa, p_s - pressure_a, dp_t);
  const double supply_to_b = orifice_flow(K, open_pb, p_s - pressure_b, dp_t);
  return {supply_to_a - orifice_flow(K, open_pb, pressure_a - p_t, dp_t),
          supply_to_b - orifice_flow(K, open_pa, pressure_b - p_t, dp_t), supply_to_a + supply_to_b};
}

}  // namespace heavesim
