// Controllers and sensors against hand-derived responses: the PID's back-calculation
// anti-windup under a held error (closed-form exponential of the integral state); the
// closed loop of a mass, a lagged force actuator and the PID (derivative on the
// measurement) against the matrix exponential of its linear state equations; the MRU's
// steady sinusoidal response against its transfer function; and the stroke-loop poles
// against the roots of the characteristic polynomial.
#include <gtest/gtest.h>

#include <unsupported/Eigen/MatrixFunctions>
#include <unsupported/Eigen/Polynomials>

#include <cmath>
#include <complex>

#include "control/active/active_compensator.hpp"
#include "control/analysis/stroke_loop.hpp"
#include "control/pneumatic/pneumatic_compensator.hpp"
#include "kernel/system/multibody_system.hpp"
#include "tests/control/integration.hpp"
#include "samples/oscillators.hpp"
#include "validation/checks/prescribed_motion.hpp"

namespace heavesim {
namespace {

/// docs/physics/drilling-rig.md §5 defaults: pole placement on 290 t, w_c = 2 rad/s, zeta = 0.8.
ActiveCompensatorParameters default_force_control() {
  ActiveCompensatorParameters p;
  const double mass = 290e3, w = 2.0, zeta = 0.8;
  p.gains.proportional = mass * w * w;
  p.gains.derivative = 2 * zeta * mass * w;
  p.gains.integral = 0.1 * w * p.gains.proportional;
  p.force_actuator = {0.1, 3.9e5, std::numeric_limits<double>::infinity()};
  p.controlled_point = BodyPoint{1, Vector3::Zero()};
  return p;
}

/// A 290 t load held at mid-stroke (prescribed: it cannot move) under the compensator
/// `p`, whose controlled height is set 0.5 m below the load: e = -0.5 m throughout.
std::unique_ptr<validation::PrescribedMotionSystem> held_half_a_metre_high(ActiveCompensatorParameters p) {
  auto model = samples::vertical_slider(290e3);
  auto system = std::make_unique<validation::PrescribedMotionSystem>(model, [](double, VectorX& q, VectorX& v) {
    q[0] = 0.0;
    v[0] = 0.0;
  });
  p.controlled_height = -0.5;  // z_c - z_c(0) = +0.5 m: the load sits 0.5 m above where it should be
  system->add_force_element(std::make_unique<ActiveCompensator>("active", StrokeAxis::on_joint(*model, 1, 0.0), p));
  return system;
}

TEST(Pid, BackCalculationAntiWindupUnderAHeldError) {
  // The load is held 0.5 m above its reference, so e = -0.5 m and the command
  // saturates at -F_max. With u = K_p e + K_i I (no motion, no derivative term),
  // dI/dt = e + (-F_max - u) / (K_i T_t) is linear:
  //   I(t) = I* (1 - exp(-t / T_t)),  I* = T_t e + (-F_max - K_p e) / K_i.
  const ActiveCompensatorParameters p = default_force_control();
  const double e = -0.5, K_p = p.gains.proportional, K_i = p.gains.integral;
  const double T_t = std::sqrt(p.gains.derivative / K_i);  // Astrom's default
  auto held = held_half_a_metre_high(p);
  validation::PrescribedMotionSystem& system = *held;
  auto integrator = testing::start_integrator(system, system.initial_state(), IntegrationMethod::dopri5, 1e-12, 1e-14);
  const double I_star = T_t * e + (-3.9e5 - K_p * e) / K_i;  // saturated at -F_max
  for (double t : {0.5, 2.0, 10.0}) {
    integrator->advance_to(t);
    const double I = I_star * (1.0 - std::exp(-t / T_t));
    EXPECT_NEAR(integrator->state()[0], I, 1e-9 * std::abs(I_star)) << "t = " << t;
    system.place(t);
    const auto& element = static_cast<const ActiveCompensator&>(system.element(0));
    const ActiveState s = element.evaluate(t, system.model(), system.data(), integrator->state().head(2), nullptr);
    EXPECT_NEAR(s.command, K_p * e + K_i * I, 1e-6);
    EXPECT_EQ(s.saturated_command, -3.9e5);
  }
  // Without anti-windup the integral would be e t = -5 m s at 10 s; it stays bounded near I*.
  EXPECT_GT(integrator->state()[0], I_star - 1e-6);
}

TEST(Pid, ClosedLoopStepMatchesTheMatrixExponential) {
  // A 290 t mass (no gravity) under the default PID and a 0.1 s actuator lag, asked to
  // move 0.1 m (reference step). Linear, unsaturated: x = [z, dz/dt, I, F/m],
  //   z' = v, m v' = F, I' = 0.1 - z, tau F' = K_p (0.1 - z) + K_i I - K_d v - F,
  // x(t) = x* + expm(A t) (x0 - x*) with x* = [0.1, 0, 0, 0]. (F/m, not F: the
  // matrix exponential loses digits when A's entries span 14 decades.)
  const double m = 290e3;
  auto model = samples::vertical_slider(m, Vector3::Zero());
  ActiveCompensatorParameters p = default_force_control();
  p.force_actuator.max_force = 1e9;  // stays linear
  p.controlled_height = 0.1;
  const double K_p = p.gains.proportional, K_i = p.gains.integral, K_d = p.gains.derivative, tau = 0.1;
  MultibodySystem system(model);
  system.add_force_element(std::make_unique<ActiveCompensator>("active", StrokeAxis::on_joint(*model, 1, 0.0), p));
  ASSERT_EQ(system.size(), 4);  // q, v, I, F/F_max
  auto integrator = testing::start_integrator(system, system.initial_state(VectorX::Zero(1), VectorX::Zero(1)),
                                              IntegrationMethod::ida, 1e-11, 1e-13);

  Eigen::Matrix4d A;
  A << 0, 1, 0, 0,           //
      0, 0, 0, 1,            //
      -1, 0, 0, 0,           //
      -K_p / (m * tau), -K_d / (m * tau), K_i / (m * tau), -1 / tau;
  const Eigen::Vector4d x_star(0.1, 0, 0, 0), x0 = Eigen::Vector4d::Zero();
  double error = 0.0;
  for (int k = 1; k <= 40; ++k) {
    const double t = 0.5 * k;
    integrator->advance_to(t);
    const Eigen::Vector4d x = x_star + (Eigen::Matrix4d(A * t)).exp() * (x0 - x_star);
    error = std::max(error, std::abs(integrator->state()[0] - x[0]));
    EXPECT_NEAR(integrator->state()[3] * 1e9, m * x[3], 1e-3) << "actuator force [N] at t = " << t;
  }
  EXPECT_LT(error, 1e-8);
}

TEST(Pid, StrokeCentringMatchesTheMatrixExponential) {
  // The load starts 0.5 m off mid-stroke, held there (no error); centring lets the
  // reference drift, dr/dt = -(s - 0) / T_c, and the PID loop follows it. With the
  // platform still, s = z and x = [z, v, I, F/m, r, 1] is linear:
  //   z' = v, v' = F/m, I' = r - (z - 0.5), tau F' = K_p (r - z + 0.5) + K_i I - K_d v - F,
  //   r' = -z / T_c;  x(t) = expm(A t) x0 (the constant 1 carries the offsets).
  const double m = 290e3, T_c = 30.0;
  auto model = samples::vertical_slider(m, Vector3::Zero());
  ActiveCompensatorParameters p = default_force_control();
  p.force_actuator.max_force = 1e9;
  p.centring_time = T_c;
  p.controlled_height = 0.5;  // the initial state is the reference
  const double K_p = p.gains.proportional, K_i = p.gains.integral, K_d = p.gains.derivative, tau = 0.1;
  MultibodySystem system(model);
  system.add_force_element(std::make_unique<ActiveCompensator>("active", StrokeAxis::on_joint(*model, 1, 0.0), p));
  ASSERT_EQ(system.size(), 5);  // q, v, I, r, F/F_max
  auto integrator = testing::start_integrator(system, system.initial_state(VectorX::Constant(1, 0.5), VectorX::Zero(1)),
                                              IntegrationMethod::ida, 1e-11, 1e-13);
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  A(0, 1) = 1;
  A(1, 3) = 1;
  A(2, 0) = -1, A(2, 4) = 1, A(2, 5) = 0.5;
  A(3, 0) = -K_p / (m * tau), A(3, 1) = -K_d / (m * tau), A(3, 2) = K_i / (m * tau), A(3, 3) = -1 / tau;
  A(3, 4) = K_p / (m * tau), A(3, 5) = 0.5 * K_p / (m * tau);
  A(4, 0) = -1 / T_c;
  Eigen::Matrix<double, 6, 1> x0;
  x0 << 0.5, 0, 0, 0, 0, 1;
  double error = 0.0;
  for (int k = 1; k <= 24; ++k) {
    const double t = 5.0 * k;  // four centring time constants
    integrator->advance_to(t);
    const Eigen::Matrix<double, 6, 1> x = Eigen::Matrix<double, 6, 6>(A * t).exp() * x0;
    error = std::max(error, std::abs(integrator->state()[0] - x[0]));
    EXPECT_NEAR(integrator->state()[3], x[4], 1e-8) << "reference at t = " << t;
  }
  EXPECT_LT(error, 1e-8);
  EXPECT_LT(std::abs(integrator->state()[0]), 0.5 * std::exp(-3.0));  // it did centre
}

TEST(ForceActuator, RateLimitThenLag) {
  // A held error saturates the command at -F_max. The force ramps at -r_max while
  // (u - F) / tau exceeds r_max, i.e. until |u - F| = r_max tau at t1 = (F_max - r_max tau) / r_max,
  // then closes the remaining r_max tau exponentially with tau.
  ActiveCompensatorParameters p = default_force_control();
  p.gains.integral = p.gains.derivative = 0.0;
  p.force_actuator.max_rate = 1e5;  // e = -0.5 m: u = K_p e = -5.8e5 N, saturated at -3.9e5 N
  auto held = held_half_a_metre_high(p);
  validation::PrescribedMotionSystem& system = *held;
  auto integrator = testing::start_integrator(system, system.initial_state(), IntegrationMethod::dopri5, 1e-12, 1e-14);
  const double r = 1e5, tau = 0.1, F_max = 3.9e5, t1 = (F_max - r * tau) / r;
  for (double t : {1.0, 3.0, t1, t1 + 0.1, t1 + 0.5}) {
    integrator->advance_to(t);
    const double F = t <= t1 ? -r * t : -F_max + r * tau * std::exp(-(t - t1) / tau);
    EXPECT_NEAR(integrator->state()[0] * F_max, F, 1e-3) << "t = " << t;
  }
}

TEST(MotionReferenceUnit, SteadySinusoidMatchesTheTransferFunction) {
  // The base heaves a sin(w t); the MRU reports it through
  // H(s) = s^2 / (s^2 + 2 zeta w_c s + w_c^2) / (1 + tau s): after the filter
  // transient, heave = Im(a H(iw) e^{iwt}), rate and acceleration likewise with iw, -w^2.
  auto model = samples::base_and_load(1e6, 3e5, Vector3::Zero());
  const double a = 1.3, w = 2 * M_PI / 10.0;
  validation::PrescribedMotionSystem system(model, [=](double t, VectorX& q, VectorX& v) {
    q << a * std::sin(w * t), 0.0;
    v << a * w * std::cos(w * t), 0.0;
  });
  ActiveCompensatorParameters p = default_force_control();
  p.gains = PidGains{};  // the sensor alone
  p.mru = MruParameters{20.0, 0.7071067811865476, 0.05};
  p.controlled_point = BodyPoint{2, Vector3::Zero()};
  system.add_force_element(std::make_unique<ActiveCompensator>("active", StrokeAxis::on_joint(*model, 2, 0.0), p));
  auto integrator = testing::start_integrator(system, system.initial_state(), IntegrationMethod::dopri5, 1e-12, 1e-13);

  const std::complex<double> s(0.0, w);
  const double w_c = 2 * M_PI / 20.0;
  const std::complex<double> H = s * s / (s * s + 2 * 0.7071067811865476 * w_c * s + w_c * w_c) / (1.0 + 0.05 * s);
  double error[3] = {0, 0, 0};
  for (int k = 0; k <= 50; ++k) {
    const double t = 300.0 + 0.2 * k;  // 15 corner periods in: the transient is e^-{45}
    integrator->advance_to(t);
    system.place(t);
    const auto& element = static_cast<const ActiveCompensator&>(system.element(0));
    const ActiveState state = element.evaluate(0.0, *model, system.data(), integrator->state().head(4), nullptr);
    const std::complex<double> phasor = a * H * std::exp(std::complex<double>(0.0, w * t));
    error[0] = std::max(error[0], std::abs(state.platform_heave - phasor.imag()));
    error[1] = std::max(error[1], std::abs(state.platform_heave_rate - (s * phasor).imag()));
    error[2] = std::max(error[2], std::abs(state.platform_heave_acceleration - (s * s * phasor).imag()));
  }
  EXPECT_LT(error[0], 1e-8 * a);
  EXPECT_LT(error[1], 1e-8 * a * w);
  EXPECT_LT(error[2], 1e-8 * a * w * w);
  // The filter's phase lead at T = 10 s with a 20 s corner is large: a real effect to see.
  EXPECT_GT(std::arg(H), 0.3);
}

TEST(StrokeLoop, PolesAreTheRootsOfTheCharacteristicPolynomial) {
  // Gas spring k, mass m, PID with actuator lag tau (true measurement):
  //   m tau s^4 + m s^3 + (k tau + K_d) s^2 + (k + K_p) s + K_i = 0.
  const double m = 290e3;
  PneumaticParameters pneumatic;
  const double k = 1.4 * 15e6 * 0.1735 * 0.1735 / 60.0;
  ActiveCompensatorParameters active = default_force_control();
  const double K_p = active.gains.proportional, K_i = active.gains.integral, K_d = active.gains.derivative;
  std::vector<StrokeElementFactory> elements = {
      [&](const Model&, const StrokeAxis& axis) { return std::make_unique<PneumaticCompensator>("pn", axis, pneumatic); },
      [&](const Model&, const StrokeAxis& axis) {
        ActiveCompensatorParameters p = active;
        p.controlled_point = BodyPoint{1, Vector3::Zero()};
        return std::make_unique<ActiveCompensator>("active", axis, p);
      }};
  const StrokeLoopPoles poles = stroke_loop_poles(m, elements);
  Eigen::VectorXd coefficients(5);  // ascending powers
  coefficients << K_i, k + K_p, k * 0.1 + K_d, m, m * 0.1;
  Eigen::PolynomialSolver<double, 4> solver(coefficients);
  ASSERT_EQ(poles.poles.size(), 4u);
  for (const std::complex<double>& root : solver.roots()) {
    double nearest = 1e300;
    for (const std::complex<double>& pole : poles.poles) nearest = std::min(nearest, std::abs(pole - root));
    EXPECT_LT(nearest, 1e-6 * std::abs(root)) << root;
  }
  EXPECT_LT(poles.largest_real_part, 0.0);

  // P control through the lag alone is unstable: m tau s^3 + m s^2 + K_p = 0 has a
  // root in the right half-plane (Routh: 0 * m - m tau K_p < 0).
  active.gains.derivative = active.gains.integral = 0.0;
  EXPECT_GT(stroke_loop_poles(m, {elements[1]}).largest_real_part, 0.1);
}

}  // namespace
}  // namespace heavesim
