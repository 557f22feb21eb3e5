// The hydraulic actuator against closed forms: the orifice law's turbulent and laminar
// limits and the datasheet rating; the valve's port connections; the chamber pressure
// rates written out by hand; the steady pressures of a cylinder extending at constant
// speed through a fully open valve; and the blocked cylinder's hydraulic natural
// frequency omega_h = sqrt(beta (A_A^2/V_A + A_B^2/V_B) / m) from a free oscillation.
#include <gtest/gtest.h>

#include <cmath>

#include "control/active/active_compensator.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/system/multibody_system.hpp"
#include "tests/control/integration.hpp"
#include "samples/oscillators.hpp"
#include "validation/checks/prescribed_motion.hpp"

namespace heavesim {
namespace {

TEST(Orifice, TurbulentAndLaminarLimitsAndRating) {
  ServoValveParameters valve;  // Q_N = 0.02 m^3/s at 35 bar, laminar below ~1 bar
  const double K = valve.flow_coefficient();
  // Turbulent: sqrt law, relative deviation (1 + (dp_t/dp)^2)^(-1/4) - 1 ~ -(dp_t/dp)^2 / 4.
  for (double dp : {1e7, 3.5e6, -2e6}) {
    const double Q = orifice_flow(K, 0.6, dp, valve.transition_pressure);
    const double sqrt_law = 0.6 * K * std::copysign(std::sqrt(std::abs(dp)), dp);
    EXPECT_NEAR(Q / sqrt_law - 1.0, -0.25 * std::pow(valve.transition_pressure / dp, 2), 1e-6);
  }
  // At the rating the laminar blending lowers the flow by (dp_t / dp_N)^2 / 4 = 2.04e-4.
  EXPECT_NEAR(orifice_flow(K, 1.0, valve.rated_pressure_drop, valve.transition_pressure), 0.02, 0.02 * 2.1e-4);
  // Laminar: finite slope K x / sqrt(dp_t) through zero (no infinite Jacobian entry).
  const double h = 1.0;  // Pa
  const double slope = (orifice_flow(K, 0.6, h, 1e5) - orifice_flow(K, 0.6, -h, 1e5)) / (2 * h);
  EXPECT_NEAR(slope, 0.6 * K / std::sqrt(1e5), 1e-8 * slope);
  EXPECT_EQ(orifice_flow(K, 0.6, 0.0, 1e5), 0.0);
}

TEST(ServoValve, PortsFollowTheSpool) {
  ServoValveParameters valve;
  valve.transition_pressure = 1.0;  // effectively the pure sqrt law
  const HydraulicSupply supply{21e6, 2e5};
  const double K = valve.flow_coefficient();
  const ValveFlows extend = valve_flows(valve, supply, 0.5, 12e6, 6e6);
  EXPECT_NEAR(extend.into_a, 0.5 * K * std::sqrt(21e6 - 12e6), 1e-9);   // P -> A
  EXPECT_NEAR(extend.into_b, -0.5 * K * std::sqrt(6e6 - 2e5), 1e-9);    // B -> T
  EXPECT_NEAR(extend.supply, extend.into_a, 1e-12);
  const ValveFlows retract = valve_flows(valve, supply, -0.25, 12e6, 6e6);
  EXPECT_NEAR(retract.into_a, -0.25 * K * std::sqrt(12e6 - 2e5), 1e-9);  // A -> T
  EXPECT_NEAR(retract.into_b, 0.25 * K * std::sqrt(21e6 - 6e6), 1e-9);   // P -> B
  const ValveFlows closed = valve_flows(valve, supply, 0.0, 12e6, 6e6);
  EXPECT_EQ(closed.into_a, 0.0);
  EXPECT_EQ(closed.into_b, 0.0);
  // Underlap: at null every land is open by x_u; near null both P->A and A->T flow.
  valve.underlap = 0.02;
  const ValveFlows null = valve_flows(valve, supply, 0.0, 12e6, 6e6);
  EXPECT_NEAR(null.into_a, 0.02 * K * (std::sqrt(21e6 - 12e6) - std::sqrt(12e6 - 2e5)), 1e-12);
  EXPECT_NEAR(null.into_b, 0.02 * K * (std::sqrt(21e6 - 6e6) - std::sqrt(6e6 - 2e5)), 1e-12);
  EXPECT_NEAR(null.supply, 0.02 * K * (std::sqrt(21e6 - 12e6) + std::sqrt(21e6 - 6e6)), 1e-12);
  const ValveFlows beyond = valve_flows(valve, supply, 0.5, 12e6, 6e6);  // A->T and P->B lands closed
  EXPECT_NEAR(beyond.into_a, 0.52 * K * std::sqrt(21e6 - 12e6), 1e-12);
  EXPECT_NEAR(beyond.into_b, -0.52 * K * std::sqrt(6e6 - 2e5), 1e-12);
}

ActiveCompensatorParameters hydraulic_actuator() {
  ActiveCompensatorParameters p;
  p.actuator = ActuatorType::hydraulic;
  p.hydraulic.cylinder.internal_leakage = 2e-12;
  p.hydraulic.cylinder.external_leakage = 1e-12;
  return p;
}

TEST(HydraulicCylinder, PressureRatesSpoolAndForceAsWrittenByHand) {
  // base_and_load: the base heaves, the load strokes on it; the element's rates
  // against the equations of docs/physics/compensators.md §8-9 written out here.
  auto model = samples::base_and_load(1e6, 3e5);
  Data data(*model);
  VectorX q(2), v(2);
  q << 0.4, 1.2;
  v << -0.3, 0.25;
  update_positions(*model, data, q);
  update_velocities(*model, data, q, v);
  ActiveCompensatorParameters p = hydraulic_actuator();
  p.gains.proportional = 0.3;  // P only: no controller state
  p.controlled_point = BodyPoint{2, Vector3::Zero()};
  const ActiveCompensator element("active", StrokeAxis::on_joint(*model, 2, 0.0), p);
  ASSERT_EQ(element.state_size(), 4);
  VectorX z(4), zdot(4);
  z << 0.3, 0.4, 0.55, 0.3;  // x_v, (dx_v/dt)/w_v, p_A/p_S, p_B/p_S
  element.state_derivative(0.0, *model, data, z, zdot);

  const double p_s = 21e6, p_t = 2e5, beta = 1e9, A_a = 0.03, A_b = 0.015, C_i = 2e-12, C_e = 1e-12;
  const double w_v = 2 * M_PI * 30.0, K = 0.02 / std::sqrt(3.5e6);
  auto g = [](double dp) { return dp / std::pow(dp * dp + 1e10, 0.25); };  // dp_t = 1e5 Pa
  const double p_a = 0.55 * p_s, p_b = 0.3 * p_s;
  const double V_a = 0.15 + A_a * 1.2, V_b = 0.08 - A_b * 1.2;
  const double Q_a = K * 0.3 * g(p_s - p_a), Q_b = -K * 0.3 * g(p_b - p_t);
  const double pa_rate = beta / V_a * (Q_a - A_a * 0.25 - C_i * (p_a - p_b) - C_e * (p_a - p_t));
  const double pb_rate = beta / V_b * (Q_b + A_b * 0.25 + C_i * (p_a - p_b) - C_e * (p_b - p_t));
  EXPECT_NEAR(zdot[2] * p_s, pa_rate, 1e-9 * std::abs(pa_rate));
  EXPECT_NEAR(zdot[3] * p_s, pb_rate, 1e-9 * std::abs(pb_rate));
  // Stroke-speed demand v_d = K_p e, e = 0 - z_load = -(0.4 + 1.2) m; retracting, so the
  // spool opening passes A_A v_d through the A -> T land: x_c = A_A v_d / (K sqrt(p_A - p_T));
  // then x'' = w^2 (x_c - x) - 2 zeta w x'.
  const double v_d = 0.3 * -(0.4 + 1.2);
  const double u = A_a * v_d / (K * std::sqrt(p_a - p_t));
  EXPECT_NEAR(zdot[0] * w_v, w_v * w_v * 0.4, 1e-9);  // x' = w_v * 0.4 -> its rate in z units
  EXPECT_NEAR(zdot[1] * w_v, w_v * w_v * (u - 0.3) - 2 * 0.7 * w_v * (w_v * 0.4), 1e-6);
  const ActiveState state = element.evaluate(0.0, *model, data, z, nullptr);
  EXPECT_NEAR(state.force, p_a * A_a - p_b * A_b - 101325.0 * (A_a - A_b), 1e-6);
  EXPECT_NEAR(state.supply_power, (p_s - p_t) * Q_a, 1e-6);
  EXPECT_NEAR(state.valve_command, u, 1e-12);
}

TEST(HydraulicCylinder, SteadyPressuresWhenExtendingThroughAnOpenValve) {
  // The base moves down at 0.4 m/s; velocity feed-forward saturates the valve fully
  // open; the stroke extends at 0.3 m/s. The pressures settle where the orifice flows
  // equal the displaced flows: K g(p_S - p_A) = A_A v and K g(p_B - p_T) = A_B v,
  // solved here by bisection on the orifice law written out.
  auto model = samples::base_and_load(1e6, 3e5);
  validation::PrescribedMotionSystem system(model, [](double t, VectorX& q, VectorX& v) {
    q << -0.4 * t, 0.3 * t;
    v << -0.4, 0.3;
  });
  ActiveCompensatorParameters p = hydraulic_actuator();
  p.hydraulic.cylinder.internal_leakage = p.hydraulic.cylinder.external_leakage = 0.0;
  p.velocity_feedforward = 10.0;  // v_d = -10 * (-0.4) = 4 m/s: beyond what the open valve passes
  p.controlled_point = BodyPoint{2, Vector3::Zero()};
  system.add_force_element(std::make_unique<ActiveCompensator>("active", StrokeAxis::on_joint(*model, 2, 0.0), p));
  // IDA: the pressures are stiff.
  auto integrator = testing::start_integrator(system, system.initial_state(), IntegrationMethod::ida, 1e-10, 1e-12);
  integrator->advance_to(2.0);
  system.place(2.0);
  const auto& element = static_cast<const ActiveCompensator&>(system.element(0));
  const ActiveState state = element.evaluate(0.0, *model, system.data(), integrator->state().head(4), nullptr);

  const double K = 0.02 / std::sqrt(3.5e6);
  auto g = [](double dp) { return dp / std::pow(dp * dp + 1e10, 0.25); };
  auto drop_for = [&](double flow) {  // dp with K g(dp) = flow
    double low = 0.0, high = 1e8;
    for (int k = 0; k < 200; ++k) ((K * g(0.5 * (low + high)) < flow) ? low : high) = 0.5 * (low + high);
    return 0.5 * (low + high);
  };
  EXPECT_NEAR(state.spool_position, 1.0, 1e-9);
  EXPECT_NEAR(state.pressure_a, 21e6 - drop_for(0.03 * 0.3), 1.0);
  EXPECT_NEAR(state.pressure_b, 2e5 + drop_for(0.015 * 0.3), 1.0);
  EXPECT_NEAR(state.flow_a, 0.03 * 0.3, 1e-9);
}

TEST(HydraulicCylinder, BlockedCylinderOscillatesAtTheHydraulicNaturalFrequency) {
  // Zero gains: the spool stays closed, the cylinder is a blocked oil spring. A mass
  // m released with speed v0 at s = 0 oscillates as s = (v0 / w_h) sin(w_h t).
  const double m = 2e4;
  auto model = samples::vertical_slider(m, Vector3::Zero());
  ActiveCompensatorParameters p = hydraulic_actuator();
  p.hydraulic.cylinder.internal_leakage = p.hydraulic.cylinder.external_leakage = 0.0;
  const auto& c = p.hydraulic.cylinder;
  const double omega_h = std::sqrt(c.bulk_modulus * (c.area_a * c.area_a / c.volume_a + c.area_b * c.area_b / c.volume_b) / m);
  MultibodySystem system(model);
  system.add_force_element(std::make_unique<ActiveCompensator>("active", StrokeAxis::on_joint(*model, 1, 0.0), p));
  const double v0 = 1e-4;  // amplitude v0/w_h ~ 2 um: the linearization error is ~1e-5 of it
  auto integrator = testing::start_integrator(system, system.initial_state(VectorX::Zero(1), VectorX::Constant(1, v0)),
                                              IntegrationMethod::ida, 1e-11, 1e-14);
  const double amplitude = v0 / omega_h;
  double error = 0.0;
  for (int k = 1; k <= 200; ++k) {
    const double t = k * (5 * 2 * M_PI / omega_h) / 200;  // five periods
    integrator->advance_to(t);
    error = std::max(error, std::abs(integrator->state()[0] - amplitude * std::sin(omega_h * t)));
  }
  EXPECT_LT(error, 1e-4 * amplitude) << "omega_h = " << omega_h;
}

}  // namespace
}  // namespace heavesim
