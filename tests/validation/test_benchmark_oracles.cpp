// The IFToMM benchmark oracles (validation/oracles, docs/physics/benchmarks.md) against
// published numbers and against each other's independent formulations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "validation/oracles/bricard_mechanism.hpp"
#include "validation/oracles/flyball_governor.hpp"
#include "validation/oracles/four_bar_parallelogram.hpp"
#include "validation/oracles/reference_integrator.hpp"
#include "validation/oracles/simple_pendulum.hpp"

namespace heavesim::oracle {
namespace {

TEST(BenchmarkOracles, NFourBarWithFortyWindowsMatchesThePublishedAngleAtTenSeconds) {
  // A02 with N = 40: the exact crank angle at t = 10 s and B0 relative to its pin in
  // the benchmark's convention (B0 moving along +x): (sin q, cos q).
  const std::vector<double> angles = four_bar_crank_angles(40, 9.81, {10.0}, 1e-13);
  EXPECT_NEAR(angles[0], 31.5974337440, 1e-9);
  EXPECT_NEAR(std::sin(angles[0]), 0.1805122267, 1e-9);
  EXPECT_NEAR(std::cos(angles[0]), 0.9835727406, 1e-9);
}

TEST(BenchmarkOracles, ParallelogramOracleReducesToTheNFourBar) {
  // Upright cranks are hanging cranks turned by pi: q_hanging = q_upright + pi.
  const int windows = 2;
  const double first = (windows + 1) * 0.5 + windows, second = (windows + 1) / 3.0 + windows;
  const std::vector<double> times = {0.5, 3.0, 10.0};
  const std::vector<double> upright = four_bar_crank_angles(windows, 9.81, times, 1e-13);
  const std::vector<double> hanging =
      parallelogram_crank_angles(first, second, 9.81, std::numbers::pi, 1.0, times, 1e-13);
  for (std::size_t k = 0; k < times.size(); ++k) EXPECT_NEAR(hanging[k], upright[k] + std::numbers::pi, 1e-9);
}

TEST(BenchmarkOracles, EllipticFunctionsMatchTabulatedValues) {
  // K(1/2) = Gamma(1/4)^2 / (4 sqrt(pi)) = 1.85407 46773 01372 (Abramowitz & Stegun, Table 17.1).
  EXPECT_NEAR(complete_elliptic_integral_k(0.5), 1.8540746773013719, 1e-15);
  EXPECT_NEAR(complete_elliptic_integral_k(0.0), std::numbers::pi / 2, 1e-15);
  const double quarter = complete_elliptic_integral_k(0.5);
  EXPECT_NEAR(jacobi_sn_cn(quarter, 0.5).sn, 1.0, 1e-15);
  EXPECT_NEAR(jacobi_sn_cn(quarter, 0.5).cn, 0.0, 1e-15);
  for (double u : {-7.3, -0.4, 0.0, 0.9, 2.5, 60.0}) {
    EXPECT_NEAR(jacobi_sn_cn(u, 0.0).sn, std::sin(u), 1e-14);  // m = 0: circular functions
    const JacobiSnCn value = jacobi_sn_cn(u, 0.5);
    EXPECT_NEAR(value.sn * value.sn + value.cn * value.cn, 1.0, 1e-15);
    // sn is odd and 4K-periodic.
    EXPECT_NEAR(jacobi_sn_cn(-u, 0.5).sn, -value.sn, 1e-14);
    EXPECT_NEAR(jacobi_sn_cn(u + 4 * quarter, 0.5).sn, value.sn, 1e-13);
  }
}

TEST(BenchmarkOracles, ExactPendulumMatchesAnIndependentIntegration) {
  // theta'' = -(g/L) sin theta integrated by ARKODE Fehlberg 8(7) from rest at pi/2.
  const std::vector<double> times = {0.3, 1.7, 5.0, 10.0};
  const Rhs rhs = [](double, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
    ydot[0] = y[1];
    ydot[1] = -9.81 * std::sin(y[0]);
  };
  const std::vector<Eigen::VectorXd> integrated =
      integrate_reference(rhs, 0.0, Eigen::Vector2d(std::numbers::pi / 2, 0.0), times, 1e-13, 1e-13);
  for (std::size_t k = 0; k < times.size(); ++k)
    EXPECT_NEAR(pendulum_angle(std::numbers::pi / 2, 1.0, 9.81, times[k]), integrated[k][0], 1e-10);
  // Period 4 K(1/2) sqrt(L/g): back at theta0.
  const double period = 4 * complete_elliptic_integral_k(0.5) / std::sqrt(9.81);
  EXPECT_NEAR(pendulum_angle(std::numbers::pi / 2, 1.0, 9.81, 7 * period), std::numbers::pi / 2, 1e-12);
}

// The governor's mechanical energy, written here from the geometry (rods, balls, slider,
// shaft about the axis; gravity along -z; the two springs' elastic energy).
double flyball_energy(const FlyballGovernorParameters& p, const FlyballGovernorState& state) {
  const double c = 0.5 * p.rod_length, sine = std::sin(state.arm_angle), cosine = std::cos(state.arm_angle);
  const double axial = p.rod_mass * 2 * p.rod_section * p.rod_section / 12;
  const double transverse = p.rod_mass * (p.rod_length * p.rod_length + p.rod_section * p.rod_section) / 12;
  const double spin_inertia =
      p.shaft_axial_inertia + p.slider_axial_inertia +
      2 * (axial * sine * sine + transverse * cosine * cosine + p.rod_mass * std::pow(p.pin_offset + c * cosine, 2) +
           p.ball_mass * std::pow(p.pin_offset + p.rod_length * cosine, 2));
  const double arm_inertia = 2 * (transverse + p.rod_mass * c * c + p.ball_mass * p.rod_length * p.rod_length);
  const double kinetic = 0.5 * arm_inertia * state.arm_rate * state.arm_rate +
                         0.5 * p.slider_mass * state.slider_rate * state.slider_rate +
                         0.5 * spin_inertia * state.spin_rate * state.spin_rate;
  const double spring_length = std::hypot(c * cosine, p.pin_height - c * sine - state.slider_height);
  const double potential = -2 * p.gravity * sine * (p.rod_mass * c + p.ball_mass * p.rod_length) +
                           p.slider_mass * p.gravity * state.slider_height +
                           2 * 0.5 * p.stiffness * std::pow(spring_length - p.rest_length, 2);
  return kinetic + potential;
}

TEST(BenchmarkOracles, FlyballGovernorConservesEnergyWithoutDampingAndLosesItWith) {
  const std::vector<double> times = {0.5, 1.0, 2.0, 5.0, 10.0};
  FlyballGovernorParameters undamped;
  undamped.damping = 0.0;
  undamped.stiffness = 1e4;  // softer: a non-stiff check of the equations of motion
  const double initial_undamped =
      flyball_energy(undamped, {undamped.theta0, 0, undamped.slider_height0, 0, undamped.spin_rate0});
  for (const FlyballGovernorState& state : flyball_governor_states(undamped, times, 1e-12))
    EXPECT_NEAR(flyball_energy(undamped, state), initial_undamped, 1e-8 * std::abs(initial_undamped));

  const FlyballGovernorParameters benchmark;
  double previous = flyball_energy(benchmark, {benchmark.theta0, 0, benchmark.slider_height0, 0, benchmark.spin_rate0});
  for (const FlyballGovernorState& state : flyball_governor_states(benchmark, times, 1e-12)) {
    const double energy = flyball_energy(benchmark, state);
    EXPECT_LE(energy, previous + 1e-9);  // the dampers only dissipate
    previous = energy;
  }
}

TEST(BenchmarkOracles, BricardFormulationConservesEnergyAndStaysOnTheLoop) {
  // From rest at the benchmark's configuration, the rods' centres at y = 0, -0.5, -1, -1,
  // -0.5 m: E(0) = sum m g y = -3 m g L. The formulation does not project back onto the
  // loop: Phi drifts with the integration error (~1e-8 over 10 s at 1e-12).
  const std::vector<BricardSample> samples = bricard_samples({0.5, 1.0, 2.0, 5.0, 10.0}, 1e-12);
  const double initial_energy = -3.0 * 9.81;
  double largest_motion = 0.0;
  for (const BricardSample& sample : samples) {
    EXPECT_NEAR(sample.energy, initial_energy, 1e-7 * 5 * 9.81);
    EXPECT_LT(sample.closure_residual, 1e-7);
    largest_motion = std::max(largest_motion, (sample.p3 - Eigen::Vector3d(1, -1, 0)).norm());
  }
  EXPECT_GT(largest_motion, 0.1);  // it moves: P3 leaves (1, -1, 0)
}

}  // namespace
}  // namespace heavesim::oracle
