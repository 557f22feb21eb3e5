#pragma once
// Hand statics of the drilling rig at rest (cases/statics/drilling_rig.yaml): the
// parameters of cases/rig/parameters.yaml and semi.yaml, written again here.
//  - Heave: the platform floats where buoyancy balances the total weight. The linear
//    hydrostatics give rho g V - C33 xi3 upward, C33 = rho g A_wp; the weights are the
//    platform's, the hoist's and the string's less the string's buoyancy:
//    W = (m_platform + m_crown + m_tb + m_td + m_string) g - rho/rho_s m_string g, so
//    xi3 = (rho g V - W) / C33.
//  - Stroke: the gas (p V^n = p0 V0^n, V = V0 + A s) holds the load on the stroke,
//    W_c = (m_crown + m_tb + m_td + m_string) g - rho/rho_s m_string g:
//    (p0 (V0/(V0 + A s))^n - p_atm) A = W_c, so s = V0/A ((p0/(W_c/A + p_atm))^(1/n) - 1),
//    and the gas pressure is then W_c/A + p_atm.
//  - Hook loads: the joint above the string carries its weight in water,
//    m_string g (1 - rho/rho_s); the compensator carries W_c.
#include <cmath>

namespace heavesim::oracle {

struct RigStatics {
  double g = 9.81, rho = 1025, rho_steel = 7850;
  double m_crown = 30000, m_tb = 25000, m_td = 45000, m_string = 190000;
  double V_hull = 45600 + 15028, A_wp = 1156;
  double extra_mass = 2e5;        // kg, platform beyond its balanced displacement
  double A_p = 0.1735, V0 = 60, n = 1.4, p_atm = 101325;
  double pressure_factor = 1.002;  // p0 / balance pressure

  double string_load() const { return m_string * g * (1.0 - rho / rho_steel); }
  double compensator_load() const { return (m_crown + m_tb + m_td) * g + string_load(); }
  double rig_mass() const { return m_crown + m_tb + m_td + m_string * (1.0 - rho / rho_steel); }
  double platform_mass() const { return rho * V_hull - rig_mass() + extra_mass; }
  double heave() const {
    const double weight = (platform_mass() + m_crown + m_tb + m_td + m_string) * g - rho / rho_steel * m_string * g;
    return (rho * g * V_hull - weight) / (rho * g * A_wp);
  }
  double balance_pressure() const { return compensator_load() / A_p + p_atm; }
  double stroke() const {
    return V0 / A_p * (std::pow(pressure_factor, 1.0 / n) - 1.0);  // p0 = factor (W_c/A + p_atm)
  }
};

}  // namespace heavesim::oracle
