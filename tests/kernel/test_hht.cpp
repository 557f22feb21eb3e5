// The index-3 HHT integrator against closed forms: the trapezoidal rule's exact
// discrete solution of an oscillator, HHT's spectral radius at high frequency, second
// order with force-element states, and a loop that cannot be closed stopping with a
// diagnosis.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "kernel/integrators/integrator.hpp"
#include "kernel/system/multibody_system.hpp"
#include "samples/loop_mechanisms.hpp"
#include "samples/oscillators.hpp"

namespace heavesim {
namespace {

/// A 1 kg block on a prismatic joint (no gravity) with a joint spring of stiffness k.
std::shared_ptr<const Model> oscillator(double stiffness) {
  return std::make_shared<const Model>(samples::prismatic_oscillator(1.0, stiffness));
}

std::unique_ptr<Integrator> hht(double step, double alpha, MultibodySystem& system) {
  IntegratorSettings settings;
  settings.method = IntegrationMethod::hht;
  settings.step = step;
  settings.hht_alpha = alpha;
  settings.relative_tolerance = settings.absolute_tolerance = 1e-12;
  return make_integrator(settings, system);
}

std::unique_ptr<Integrator> hht(double step, MultibodySystem& system) { return hht(step, 0.0, system); }

TEST(Hht, TrapezoidalRuleIsTheExactRotationByTwoArctan) {
  // Newmark's average-acceleration rule on q'' = -w^2 q is the Cayley map: from q = 1,
  // v = 0 it gives exactly q_n = cos(n theta), v_n = -w sin(n theta), theta = 2 atan(w h / 2).
  const double omega = 3.0, h = 0.05;
  MultibodySystem system(oscillator(omega * omega));
  auto integrator = hht(h, system);
  integrator->initialize(0.0, system.initial_state(VectorX::Ones(1), VectorX::Zero(1)));
  const double theta = 2.0 * std::atan(omega * h / 2.0);
  for (int n = 1; n <= 200; ++n) {
    integrator->advance_to(n * h);
    ASSERT_NEAR(integrator->state()[0], std::cos(n * theta), 1e-12) << "step " << n;
    ASSERT_NEAR(integrator->state()[1], -omega * std::sin(n * theta), 1e-11) << "step " << n;
  }
  // ... which is not cos(w t): the period stretches by theta / (w h) - 1.
  EXPECT_GT(std::abs(integrator->state()[0] - std::cos(omega * 10.0)), 1e-3);
}

TEST(Hht, MatchesHilbersRecurrenceForAnOscillator) {
  // HHT-alpha on q'' = -w^2 q, written out independently from Hilber, Hughes & Taylor
  // (1977): M a_{n+1} + (1 + alpha) K q_{n+1} - alpha K q_n = 0 with Newmark's updates,
  // gamma = 1/2 - alpha, beta = (1 - alpha)^2 / 4. Low and very high w h, where the
  // numerical damping acts (spectral radius -> (1 + alpha)/(1 - alpha)).
  for (const double alpha : {-0.05, -0.3}) {
    for (const double omega_h : {0.3, 30.0}) {
      const double h = 0.01, omega = omega_h / h, gamma = 0.5 - alpha, beta = 0.25 * (1 - alpha) * (1 - alpha);
      MultibodySystem system(oscillator(omega * omega));
      auto integrator = hht(h, alpha, system);
      integrator->initialize(0.0, system.initial_state(VectorX::Ones(1), VectorX::Zero(1)));
      double q = 1.0, v = 0.0, a = -omega * omega;
      for (int n = 1; n <= 100; ++n) {
        const double k = omega * omega;
        const double a_next = (-(1 + alpha) * k * (q + h * v + h * h * (0.5 - beta) * a) + alpha * k * q) /
                              (1 + (1 + alpha) * k * beta * h * h);
        const double q_next = q + h * v + h * h * ((0.5 - beta) * a + beta * a_next);
        v += h * ((1 - gamma) * a + gamma * a_next);
        q = q_next;
        a = a_next;
        integrator->advance_to(n * h);
        ASSERT_NEAR(integrator->state()[0], q, 1e-11) << "alpha " << alpha << ", w h " << omega_h << ", step " << n;
        ASSERT_NEAR(integrator->state()[1], v, 1e-11 * omega) << "alpha " << alpha << ", w h " << omega_h;
      }
      if (omega_h > 1.0) {  // damped by about ((1 + alpha)/(1 - alpha))^100
        EXPECT_LT(std::abs(q) + std::abs(v) / omega, 3.0 * std::pow((1 + alpha) / (1 - alpha), 100) + 1e-12);
      }
    }
  }
}

/// A force element with one state: a first-order lag z' = (k_lag q - z) / tau whose
/// output pushes back on the block, F = -z.
class LaggedSpring : public ForceElement {
 public:
  const std::string& name() const override { return name_; }
  int state_size() const override { return 1; }
  void apply(double, const Model&, const Data&, Eigen::Ref<const VectorX> z, AppliedForces& forces) const override {
    forces.joint_force[0] -= z[0];
  }
  void state_derivative(double, const Model&, const Data& data, Eigen::Ref<const VectorX> z,
                        Eigen::Ref<VectorX> zdot) const override {
    // The block's position is its link frame's z (the prismatic joint's default axis).
    zdot[0] = (4.0 * data.X_world_link[1].translation().z() - z[0]) / 0.3;
  }

 private:
  std::string name_ = "lag";
};

double lagged_error(IntegrationMethod method, double step) {
  auto model = oscillator(2.0);
  auto run = [&](IntegrationMethod m, double h) {
    MultibodySystem system(model);
    system.add_force_element(std::make_unique<LaggedSpring>());
    IntegratorSettings settings;
    settings.method = m;
    settings.step = h;
    settings.relative_tolerance = settings.absolute_tolerance = 1e-13;
    auto integrator = make_integrator(settings, system);
    integrator->initialize(0.0, system.initial_state(VectorX::Ones(1), VectorX::Zero(1)));
    integrator->advance_to(5.0);
    return VectorX(integrator->state());
  };
  const VectorX reference = run(IntegrationMethod::verner6, 0.0);
  return (run(method, step) - reference).cwiseAbs().maxCoeff();
}

TEST(Hht, SecondOrderWithForceElementStates) {
  // The element state is integrated by the same (generalized) trapezoidal rule, in the
  // same Newton iteration: the whole state converges at second order.
  const double coarse = lagged_error(IntegrationMethod::hht, 0.02), fine = lagged_error(IntegrationMethod::hht, 0.01);
  EXPECT_NEAR(std::log2(coarse / fine), 2.0, 0.1) << coarse << " " << fine;
}

TEST(Hht, UnreachableConstraintStopsWithADiagnosis) {
  // A rod of 1 m hangs from a slider driven along x at 1 m/s; its tip is tied by a 1 m
  // distance constraint to a ground point at the origin. Beyond x = 2 m the loop cannot
  // close: the run must stop there with a NumericalError, never return NaN.
  auto model = samples::tethered_slider_pendulum();
  MultibodySystem system(model);
  // x = 1 with the rod turned by pi/6: its tip (x - sin q, 0, -cos q) is 1 m from the
  // origin; the tip's distance stays 1 while q' = x' (x - sin q) / (x cos q).
  VectorX q(2), v(2);
  q << 1.0, M_PI / 6.0;
  v << 1.0, 0.5 / std::cos(M_PI / 6.0);
  const VectorX state0 = system.initial_state(q, v);
  auto integrator = hht(1e-3, system);
  integrator->initialize(0.0, state0);
  try {
    for (int k = 1; k <= 30; ++k) integrator->advance_to(0.1 * k);
    FAIL() << "ran through an unreachable configuration";
  } catch (const NumericalError& error) {
    EXPECT_GT(error.time(), 0.9);  // the tip reaches full stretch at x = 2, t = 1 s
    EXPECT_LT(error.time(), 1.01);
    EXPECT_NE(std::string(error.what()).find("Newton"), std::string::npos) << error.what();
    EXPECT_FALSE(error.suggestion().empty());
  }
  EXPECT_TRUE(integrator->state().allFinite());
}

}  // namespace
}  // namespace heavesim
