// The pneumatic compensator against closed forms: the polytropic gas law, its
// stiffness n p A^2 / V (and the default rig's published 10.5 kN/m, 33 s and +-1.6 %),
// piping loss, friction and end stops, Newton cooling, the linearized hysteresis loss
// of the thermal model, and the n_c / n_e pressure ratchet of a compression-expansion cycle.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "control/pneumatic/pneumatic_compensator.hpp"
#include "kernel/algorithms/energy.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/system/multibody_system.hpp"
#include "tests/control/integration.hpp"
#include "samples/oscillators.hpp"
#include "validation/checks/prescribed_motion.hpp"

namespace heavesim {
namespace {

using validation::PrescribedMotionSystem;

constexpr double pi = std::numbers::pi;

/// The compensator on a vertical slider, placed at stroke s and rate v.
struct Placed {
  std::shared_ptr<const Model> model = samples::vertical_slider(290e3);
  Data data{*model};
  void at(double s, double v) {
    update_positions(*model, data, VectorX::Constant(1, s));
    update_velocities(*model, data, VectorX::Constant(1, s), VectorX::Constant(1, v));
  }
  StrokeAxis axis() const { return StrokeAxis::on_joint(*model, 1, 0.0); }
};

TEST(Pneumatic, PolytropicPressureAndForce) {
  Placed placed;
  PneumaticParameters p;  // docs/physics/drilling-rig.md §5 defaults
  p.exponent_compression = p.exponent_expansion = 1.3;
  const PneumaticCompensator compensator("pn", placed.axis(), p);
  for (double s : {-3.5, -1.0, 0.0, 0.7, 3.5}) {
    placed.at(s, 0.0);
    const PneumaticState state = compensator.evaluate(0.0, *placed.model, placed.data, VectorX(), nullptr);
    const double V = 60.0 + 0.1735 * s;
    const double pressure = 15e6 * std::pow(60.0 / V, 1.3);
    EXPECT_NEAR(state.gas_volume, V, 1e-12 * V);
    EXPECT_NEAR(state.gas_pressure, pressure, 1e-12 * pressure);
    EXPECT_NEAR(state.force, (pressure - 101325.0) * 0.1735, 1e-9 * pressure);
    EXPECT_NEAR(state.gas_temperature, 288.15 * std::pow(60.0 / V, 0.3), 1e-12 * 300);
  }
}

TEST(Pneumatic, StiffnessMatchesDerivativeOfForceAndTheDefaultRig) {
  Placed placed;
  const PneumaticCompensator compensator("pn", placed.axis(), PneumaticParameters{});
  auto force = [&](double s) {
    placed.at(s, 0.0);
    return compensator.evaluate(0.0, *placed.model, placed.data, VectorX(), nullptr).force;
  };
  for (double s : {-3.0, 0.0, 2.0}) {
    placed.at(s, 0.0);
    const double k = compensator.evaluate(0.0, *placed.model, placed.data, VectorX(), nullptr).stiffness;
    const double h = 1e-3;
    const double derivative = -(force(s + h) - force(s - h)) / (2 * h);  // restoring: dF/ds < 0
    EXPECT_NEAR(k, derivative, 1e-6 * k) << "s = " << s;
  }
  // docs/physics/drilling-rig.md §5: k_pn ~ 10.5 kN/m, T_n ~ 33 s with 290 t, swings ~ +-1.6 %.
  placed.at(0.0, 0.0);
  const double k0 = compensator.evaluate(0.0, *placed.model, placed.data, VectorX(), nullptr).stiffness;
  EXPECT_NEAR(k0, 10.5e3, 0.05e3);
  EXPECT_NEAR(2 * pi * std::sqrt(290e3 / k0), 33.0, 0.5);
  placed.at(-3.81, 0.0);
  const double swing = compensator.evaluate(0.0, *placed.model, placed.data, VectorX(), nullptr).gas_pressure / 15e6 - 1.0;
  EXPECT_NEAR(swing, 0.016, 0.001);
}

TEST(Pneumatic, GasEnergyClosesTheEnergyBalanceOfAnUndampedRun) {
  // A 290 t load on the gas spring with no piping loss, friction or stops and one
  // exponent (no heat exchange) is conservative: kinetic + gravity potential + the
  // compensator's stored energy stays constant to the integrator's tolerance.
  auto model = samples::vertical_slider(290e3);
  MultibodySystem system(model);
  PneumaticParameters p;
  p.gas_pressure = 290e3 * 9.81 / p.piston_area + p.atmospheric_pressure;  // balanced at mid-stroke
  system.add_force_element(std::make_unique<PneumaticCompensator>("passive", StrokeAxis::on_joint(*model, 1, 0.0), p));
  const ForceElement& compensator = *system.force_elements().back();
  auto integrator = testing::start_integrator(system, system.initial_state(VectorX::Zero(1), VectorX::Constant(1, 0.5)),
                                              IntegrationMethod::dopri5, 1e-12, 1e-14);
  double mechanical_first = 0.0, total_first = 0.0, mechanical_swing = 0.0, total_drift = 0.0, kinetic_max = 0.0;
  for (int k = 0; k <= 400; ++k) {  // 40 s, more than one period (33 s)
    if (k > 0) integrator->advance_to(0.1 * k);
    const VectorX& y = integrator->state();
    system.evaluate(0.1 * k, y, false);
    const double kinetic = kinetic_energy(*model, system.data());
    const double mechanical = kinetic + gravity_potential_energy(*model, system.data());
    const double total = mechanical + compensator.potential_energy(*model, system.data(), y.tail(0));
    if (k == 0) mechanical_first = mechanical, total_first = total;
    kinetic_max = std::max(kinetic_max, kinetic);
    mechanical_swing = std::max(mechanical_swing, std::abs(mechanical - mechanical_first));
    total_drift = std::max(total_drift, std::abs(total - total_first));
  }
  EXPECT_NEAR(kinetic_max, 0.5 * 290e3 * 0.25, 1e-9 * kinetic_max);
  EXPECT_LT(total_drift, 1e-8 * kinetic_max);
  EXPECT_GT(mechanical_swing, 0.5 * kinetic_max);  // the gas term is what closes the balance
}

TEST(Pneumatic, OneEvaluationServesApplyRatesAndOutputsAndFollowsEveryChange) {
  // A stroke element keeps its last evaluation (kernel/elements/evaluation_key.hpp):
  // apply(), state_derivative() and outputs() must each give, at their own point, what a
  // compensator that never evaluated before gives there -- after new element states on
  // the same stages, new stages, and another Data -- and the rates what evaluate() gives.
  Placed placed;
  PneumaticParameters p;
  p.cooling = GasCooling{};  // the gas temperature ratio theta = T / T0 is an element state
  const PneumaticCompensator compensator("pn", placed.axis(), p);
  ASSERT_EQ(compensator.state_size(), 1);
  const Model& model = *placed.model;
  auto at_point = [&model](const PneumaticCompensator& element, double t, const Data& data, const VectorX& z) {
    AppliedForces forces(model);
    VectorX zdot(1);
    std::vector<double> values(element.channels().size());
    element.apply(t, model, data, z, forces);
    element.state_derivative(t, model, data, z, zdot);
    element.outputs(t, model, data, z, values);
    values.push_back(forces.joint_force[0]);
    values.push_back(zdot[0]);
    return values;
  };
  auto expect_fresh_values = [&](double t, const Data& data, const VectorX& z) {
    const PneumaticCompensator fresh("pn", placed.axis(), p);
    const std::vector<double> values = at_point(compensator, t, data, z);
    EXPECT_EQ(values, at_point(fresh, t, data, z)) << "t = " << t << ", theta = " << z[0];
    double rate = 0.0;
    const PneumaticState state = fresh.evaluate(t, model, data, z, &rate);
    EXPECT_EQ(values.back(), rate);
    EXPECT_EQ(values[values.size() - 2], state.force);  // on the joint's coordinate, along the stroke
    return values;
  };
  placed.at(0.3, 0.1);
  const std::vector<double> first = expect_fresh_values(0.0, placed.data, VectorX::Constant(1, 1.0));
  // The same stages and time, a warmer gas: the pressure must follow.
  const std::vector<double> warmer = expect_fresh_values(0.0, placed.data, VectorX::Constant(1, 1.05));
  EXPECT_NE(first, warmer);
  placed.at(-0.5, -0.2);
  const std::vector<double> moved = expect_fresh_values(0.0, placed.data, VectorX::Constant(1, 1.05));
  EXPECT_NE(moved, warmer);
  // Another Data, then back: each its own stages.
  Data other(model);
  update_positions(model, other, VectorX::Constant(1, 1.2));
  update_velocities(model, other, VectorX::Constant(1, 1.2), VectorX::Constant(1, 0.4));
  EXPECT_NE(expect_fresh_values(0.0, other, VectorX::Constant(1, 1.05)), moved);
  EXPECT_EQ(expect_fresh_values(0.0, placed.data, VectorX::Constant(1, 1.05)), moved);
}

TEST(Pneumatic, PipingFrictionAndEndStops) {
  Placed placed;
  PneumaticParameters p;
  p.piping = piping_loss_from_pipe(30.0, 0.2, 0.05, 870.0, 3.0);
  p.friction = {26e3, 5e3, 0.01};
  p.end_stops = {-3.81, 3.81, 1e8, 1e6};
  const PneumaticCompensator compensator("pn", placed.axis(), p);
  const double R = 128 * 0.05 * 30.0 / (pi * std::pow(0.2, 4));  // Hagen-Poiseuille
  const double a = pi * 0.2 * 0.2 / 4;
  const double K = 3.0 * 870.0 / (2 * a * a);
  for (double v : {-0.8, -0.004, 0.0, 0.3}) {
    placed.at(1.0, v);
    const PneumaticState s = compensator.evaluate(0.0, *placed.model, placed.data, VectorX(), nullptr);
    const double Q = 0.1735 * v;
    EXPECT_NEAR(s.gas_pressure - s.cylinder_pressure, R * Q + K * Q * std::abs(Q), 1e-6);
    EXPECT_NEAR(s.friction_force, -(26e3 * std::tanh(v / 0.01) + 5e3 * v), 1e-9);
    EXPECT_EQ(s.end_stop_force, 0.0);
    EXPECT_NEAR(s.piping_loss_power, (R * Q + K * Q * std::abs(Q)) * Q, 1e-9);
    EXPECT_GE(s.piping_loss_power, 0.0);
  }
  placed.at(-3.83, -0.1);  // 2 cm into the lower stop, still entering
  EXPECT_NEAR(compensator.evaluate(0.0, *placed.model, placed.data, VectorX(), nullptr).end_stop_force, 1e8 * 0.02 + 1e6 * 0.1, 1e-3);
  placed.at(3.82, 0.5);  // 1 cm into the upper stop
  EXPECT_NEAR(compensator.evaluate(0.0, *placed.model, placed.data, VectorX(), nullptr).end_stop_force, -(1e8 * 0.01 + 1e6 * 0.5), 1e-3);
  placed.at(3.8101, -0.5);  // leaving fast: the damper would pull; the stop lets go instead
  EXPECT_EQ(compensator.evaluate(0.0, *placed.model, placed.data, VectorX(), nullptr).end_stop_force, 0.0);
}

TEST(Pneumatic, EndStopMonitorCountsContacts) {
  EndStopMonitor monitor(EndStops{-1.0, 1.0, 1e8, 0.0});
  for (double s : {0.0, -1.1, -1.2, -0.9, 0.5, 1.05, 0.2, -1.01, -0.5}) monitor.observe(s);
  EXPECT_EQ(monitor.lower_events(), 2);
  EXPECT_EQ(monitor.upper_events(), 1);
  EXPECT_NEAR(monitor.max_penetration(), 0.2, 1e-12);
}

/// Integrates the compensator's states along a prescribed stroke s(t) with Dormand-Prince.
struct StrokeHistory {
  std::function<double(double)> s, v;
  std::unique_ptr<PrescribedMotionSystem> system;
  std::unique_ptr<Integrator> integrator;
  StrokeHistory(std::function<double(double)> stroke, std::function<double(double)> rate, PneumaticParameters p)
      : s(std::move(stroke)), v(std::move(rate)) {
    auto model = samples::vertical_slider(290e3);
    system = std::make_unique<PrescribedMotionSystem>(model, [this](double t, VectorX& q, VectorX& qd) {
      q[0] = s(t);
      qd[0] = v(t);
    });
    system->add_force_element(std::make_unique<PneumaticCompensator>("pn", StrokeAxis::on_joint(*model, 1, 0.0), p));
    integrator = testing::start_integrator(*system, system->initial_state(), IntegrationMethod::dopri5, 1e-11, 1e-12);
  }
  PneumaticState at(double t) {
    integrator->advance_to(t);
    system->place(t);
    const auto& element = static_cast<const PneumaticCompensator&>(system->element(0));
    return element.evaluate(t, system->model(), system->data(), integrator->state().head(element.state_size()), nullptr);
  }
  double work() const { return integrator->state()[system->size() - 1]; }
};

TEST(Pneumatic, NewtonCoolingAtRest) {
  PneumaticParameters p;
  p.initial_temperature = 320.0;
  p.cooling = GasCooling{25.0, 288.15};
  StrokeHistory history([](double) { return 1.5; }, [](double) { return 0.0; }, p);
  const double V = 60.0 + 0.1735 * 1.5;
  for (double t : {5.0, 25.0, 100.0}) {
    const PneumaticState s = history.at(t);
    const double T = 288.15 + (320.0 - 288.15) * std::exp(-t / 25.0);
    EXPECT_NEAR(s.gas_temperature, T, 1e-8 * T);
    EXPECT_NEAR(s.gas_pressure, 15e6 * (T / 320.0) * (60.0 / V), 1e-8 * 15e6);  // ideal gas, fixed mass
  }
}

TEST(Pneumatic, ThermalHysteresisLossPerCycleMatchesTheLinearizedClosedForm) {
  // Small sinusoidal stroke s = a sin(w t) with Newton cooling: linearizing
  // dT/dt = -(n-1) T dV/dt / V + (T_w - T)/tau and p = c T / V gives the complex
  // stiffness -dp/dV = (p0/V0) (1 + (n-1) i w tau / (1 + i w tau)), so one cycle
  // dissipates pi (A a)^2 (p0 / V0) (n - 1) w tau / (1 + w^2 tau^2).
  PneumaticParameters p;
  p.cooling = GasCooling{2.0, 288.15};
  const double a = 0.05, w = 2 * pi / 10.0, tau = 2.0, n = 1.4;
  StrokeHistory history([=](double t) { return a * std::sin(w * t); }, [=](double t) { return a * w * std::cos(w * t); }, p);
  history.at(100.0);  // ten periods: the thermal transient (tau = 2 s) is gone
  const double work_start = history.work();
  history.at(110.0);
  const double dissipated = work_start - history.work();  // the gas takes in net work
  const double expected = pi * std::pow(0.1735 * a, 2) * (15e6 / 60.0) * (n - 1) * w * tau / (1 + w * w * tau * tau);
  EXPECT_NEAR(dissipated, expected, 1e-6 * expected);  // measured 2e-8 (amplitude effects)
}

TEST(Pneumatic, CompressionAndExpansionExponentsGiveTheClosedFormPressureRatio) {
  // s(t) = -3 sin(pi t / T): compression to s = -3 at t = T/2, expansion back to 0.
  // Along p V^n_c then p V^n_e the pressure returns as p0 (V0 / V1)^(n_c - n_e).
  PneumaticParameters p;
  p.exponent_compression = 1.35;
  p.exponent_expansion = 1.2;
  p.hysteresis_speed = 1e-3;
  const double T = 20.0;
  StrokeHistory history([=](double t) { return -3.0 * std::sin(pi * t / T); },
                        [=](double t) { return -3.0 * pi / T * std::cos(pi * t / T); }, p);
  const double V1 = 60.0 - 0.1735 * 3.0;
  EXPECT_NEAR(history.at(T / 2).gas_pressure, 15e6 * std::pow(60.0 / V1, 1.35), 1e-8 * 15e6);
  EXPECT_NEAR(history.at(T).gas_pressure, 15e6 * std::pow(60.0 / V1, 1.35 - 1.2), 1e-8 * 15e6);
}

}  // namespace
}  // namespace heavesim
