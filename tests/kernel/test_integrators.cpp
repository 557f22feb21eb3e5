// Integrators on ODEs with closed-form solutions: convergence order of RK4, error of
// the adaptive methods at their tolerance, IDA on a stiff problem, failure reporting.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "kernel/integrators/integrator.hpp"

namespace heavesim {
namespace {

/// y'' = -y: y = cos t.
class HarmonicOscillator : public OdeSystem {
 public:
  int size() const override { return 2; }
  void derivative(double, const VectorX& y, VectorX& ydot) override {
    ydot[0] = y[1];
    ydot[1] = -y[0];
    ++evaluations;
  }
  long evaluations = 0;
};

/// Prothero-Robinson: y' = -lambda (y - cos t) - sin t, y(0) = 1, solution cos t; stiff for large lambda.
class ProtheroRobinson : public OdeSystem {
 public:
  int size() const override { return 1; }
  void derivative(double t, const VectorX& y, VectorX& ydot) override {
    ydot[0] = -1e6 * (y[0] - std::cos(t)) - std::sin(t);
  }
};

double rk4_error(double step) {
  HarmonicOscillator system;
  IntegratorSettings settings;
  settings.method = IntegrationMethod::rk4;
  settings.step = step;
  auto integrator = make_integrator(settings, system);
  integrator->initialize(0.0, Eigen::Vector2d(1.0, 0.0));
  integrator->advance_to(10.0);
  return std::abs(integrator->state()[0] - std::cos(10.0));
}

TEST(Integrators, Rk4IsFourthOrder) {
  const double coarse = rk4_error(0.02), fine = rk4_error(0.01);
  EXPECT_NEAR(std::log2(coarse / fine), 4.0, 0.1);
}

TEST(Integrators, Rk4LandsExactlyOnOutputTimesOffTheStepGrid) {
  HarmonicOscillator system;
  IntegratorSettings settings;
  settings.method = IntegrationMethod::rk4;
  settings.step = 0.003;
  auto integrator = make_integrator(settings, system);
  integrator->initialize(0.0, Eigen::Vector2d(1.0, 0.0));
  integrator->advance_to(0.01);
  EXPECT_DOUBLE_EQ(integrator->time(), 0.01);
  EXPECT_NEAR(integrator->state()[0], std::cos(0.01), 1e-12);
}

TEST(Integrators, ExplicitMethodsOutputsImproveWithTheToleranceDownTo1e12) {
  // Outputs every 0.05 s, shorter than the methods' steps at loose tolerances: the
  // state there must come from a step that ends on it, not from ARKODE's Hermite
  // interpolant (degree <= 5, below Verner 6(5) and Fehlberg 8(7); interpolating, both
  // levelled off at 8-9 digits on Andrews' mechanism).
  for (IntegrationMethod method : {IntegrationMethod::dopri5, IntegrationMethod::verner6, IntegrationMethod::fehlberg8}) {
    double previous = std::numeric_limits<double>::infinity();
    for (double tolerance : {1e-6, 1e-8, 1e-10, 1e-12}) {
      HarmonicOscillator system;
      IntegratorSettings settings;
      settings.method = method;
      settings.relative_tolerance = settings.absolute_tolerance = tolerance;
      auto integrator = make_integrator(settings, system);
      integrator->initialize(0.0, Eigen::Vector2d(1.0, 0.0));
      double max_error = 0.0;
      for (int k = 1; k <= 200; ++k) {
        integrator->advance_to(0.05 * k);
        max_error = std::max(max_error, std::abs(integrator->state()[0] - std::cos(0.05 * k)));
      }
      // Smaller at every tighter tolerance until round-off (measured 6.7e-15 here).
      if (max_error > 1e-13) {
        EXPECT_LT(max_error, previous) << integration_method_name(method) << " at " << tolerance;
      }
      EXPECT_LT(max_error, 1e3 * tolerance) << integration_method_name(method) << " at " << tolerance;
      previous = max_error;
    }
  }
}

TEST(Integrators, AdaptiveMethodsMeetTheirTolerance) {
  for (IntegrationMethod method : {IntegrationMethod::dopri5, IntegrationMethod::verner6,
                                   IntegrationMethod::fehlberg8, IntegrationMethod::ida}) {
    HarmonicOscillator system;
    IntegratorSettings settings;
    settings.method = method;
    settings.relative_tolerance = settings.absolute_tolerance = 1e-10;
    auto integrator = make_integrator(settings, system);
    integrator->initialize(0.0, Eigen::Vector2d(1.0, 0.0));
    double max_error = 0.0;
    for (int k = 1; k <= 20; ++k) {
      integrator->advance_to(0.5 * k);
      max_error = std::max(max_error, std::abs(integrator->state()[0] - std::cos(0.5 * k)));
    }
    // Global error stays within a few hundred local tolerances over ~1.6 periods.
    EXPECT_LT(max_error, 1e-7) << integration_method_name(method);
    EXPECT_GT(integrator->statistics().steps, 0) << integration_method_name(method);
  }
}

TEST(Integrators, IdaTakesLargeStepsOnAStiffProblem) {
  ProtheroRobinson system;
  IntegratorSettings settings;
  settings.method = IntegrationMethod::ida;
  settings.relative_tolerance = 1e-8;
  settings.absolute_tolerance = 1e-10;
  auto integrator = make_integrator(settings, system);
  integrator->initialize(0.0, VectorX::Constant(1, 1.0));
  integrator->advance_to(10.0);
  EXPECT_NEAR(integrator->state()[0], std::cos(10.0), 1e-6);
  // An explicit method would need ~ 10 / (2.8e-6) steps for stability alone.
  EXPECT_LT(integrator->statistics().steps, 5000);
}

class Exploding : public OdeSystem {
 public:
  int size() const override { return 1; }
  void derivative(double t, const VectorX&, VectorX&) override {
    throw NumericalError(t, "test failure", "test suggestion");
  }
};

TEST(Integrators, FailuresArriveAsNumericalErrorsFromEveryMethod) {
  for (IntegrationMethod method : {IntegrationMethod::rk4, IntegrationMethod::dopri5, IntegrationMethod::ida}) {
    Exploding system;
    IntegratorSettings settings;
    settings.method = method;
    auto integrator = make_integrator(settings, system);
    EXPECT_THROW(
        {
          integrator->initialize(0.0, VectorX::Zero(1));
          integrator->advance_to(1.0);
        },
        NumericalError)
        << integration_method_name(method);
  }
}

}  // namespace
}  // namespace heavesim
