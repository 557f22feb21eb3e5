// K3: runs of the validation pendulums (docs/physics/multibody.md §9, V1-V4) through the
// whole application path (YAML case -> scene -> integrator) against the planar-chain
// oracle integrated by an independent high-order integrator in absolute angles.
#include <cmath>

#include <fmt/format.h>

#include "kernel/algorithms/energy.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "samples/planar_chains.hpp"
#include "validation/checks/validation_suite.hpp"
#include "validation/oracles/planar_chain_oracle.hpp"
#include "validation/oracles/reference_integrator.hpp"

namespace heavesim::validation {
namespace {

struct PendulumRun {
  std::string id;             // V1 ... V4
  std::string case_path;
  std::vector<oracle::PlanarLink> links;
  double compare_until;       // s: chaotic chains are compared over a shorter window
};

struct RunErrors {
  double angle = 0.0, reaction = 0.0, energy_drift = 0.0;
  std::vector<double> times;
  std::vector<double> first_angle, first_rate;
};

RunErrors compare_run(const PendulumRun& run) {
  const oracle::PlanarChainOracle reference(run.links);
  const int n = reference.size();

  // Kernel run: record joint states, reactions and energy at each output time.
  std::vector<double> times;
  std::vector<VectorX> q_samples, qd_samples;
  std::vector<Eigen::Matrix3Xd> reaction_samples;
  std::vector<double> energy_samples, kinetic_samples;
  run_case(run.case_path, {}, [&](double t, const MultibodySystem& system) {
    times.push_back(t);
    q_samples.push_back(system.configuration());
    qd_samples.push_back(system.velocity());
    Eigen::Matrix3Xd reactions(3, n);
    for (int i = 0; i < n; ++i) reactions.col(i) = joint_reaction(system.model(), system.data(), i + 1).force_world;
    reaction_samples.push_back(reactions);
    kinetic_samples.push_back(kinetic_energy(system.model(), system.data()));
    energy_samples.push_back(kinetic_samples.back() + gravity_potential_energy(system.model(), system.data()));
  });

  // Oracle run from the same initial state, in absolute angles.
  VectorX y0(2 * n);
  y0 << samples::absolute_from_relative(q_samples.front()), samples::absolute_from_relative(qd_samples.front());
  const oracle::Rhs rhs = [&](double, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
    ydot.head(n) = y.tail(n);
    ydot.tail(n) = reference.accelerations(y.head(n), y.tail(n), VectorX::Zero(n));
  };
  const std::vector<Eigen::VectorXd> exact = oracle::integrate_reference(rhs, times.front(), y0, times, 1e-13, 1e-13);

  RunErrors errors;
  const double max_kinetic = *std::max_element(kinetic_samples.begin(), kinetic_samples.end());
  const double energy_scale = std::max(std::abs(energy_samples.front()), max_kinetic);
  for (std::size_t k = 0; k < times.size(); ++k) {
    errors.energy_drift = std::max(errors.energy_drift, std::abs(energy_samples[k] - energy_samples.front()) / energy_scale);
    if (times[k] > run.compare_until + 1e-12) continue;
    const VectorX theta = exact[k].head(n), theta_dot = exact[k].tail(n);
    errors.angle = std::max(errors.angle, (samples::absolute_from_relative(q_samples[k]) - theta).cwiseAbs().maxCoeff());
    const Eigen::Matrix2Xd pin = reference.pin_forces(theta, theta_dot, reference.accelerations(theta, theta_dot, VectorX::Zero(n)));
    for (int i = 0; i < n; ++i)
      errors.reaction = std::max(errors.reaction, (reaction_samples[k].col(i) - Vector3(pin(0, i), 0.0, pin(1, i))).norm());
    errors.times.push_back(times[k]);
    errors.first_angle.push_back(samples::absolute_from_relative(q_samples[k])[0]);
    errors.first_rate.push_back(qd_samples[k][0]);
  }
  return errors;
}

/// Period from successive downward zero crossings of theta (cubic Hermite on (theta, theta')).
double measured_period(const RunErrors& run) {
  std::vector<double> crossings;
  for (std::size_t k = 1; k < run.times.size(); ++k) {
    const double a = run.first_angle[k - 1], b = run.first_angle[k];
    if (!(a > 0.0 && b <= 0.0)) continue;
    const double h = run.times[k] - run.times[k - 1];
    double s = a / (a - b);  // Newton on the Hermite interpolant, from the linear guess
    for (int iteration = 0; iteration < 20; ++iteration) {
      const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
      const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
      const double value = h00 * a + h10 * h * run.first_rate[k - 1] + h01 * b + h11 * h * run.first_rate[k];
      const double d00 = 6 * s * s - 6 * s, d10 = 3 * s * s - 4 * s + 1, d01 = -6 * s * s + 6 * s, d11 = 3 * s * s - 2 * s;
      const double slope = d00 * a + d10 * h * run.first_rate[k - 1] + d01 * b + d11 * h * run.first_rate[k];
      s -= value / slope;
    }
    crossings.push_back(run.times[k - 1] + s * h);
  }
  if (crossings.size() < 2) return NAN;
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

}  // namespace

std::vector<ValidationRow> check_k3_pendulum_runs() {
  // V1: point mass on a massless 1 m rod (IFToMM A01); V2-V4: uniform 1 m, 1 kg rods.
  const std::vector<PendulumRun> runs = {
      {"V1", "cases/validation/one_link.yaml", {{1.0, 1.0, 1.0, 0.0}}, 10.0},
      {"V2", "cases/validation/two_link.yaml", oracle::unit_rods(2), 10.0},
      {"V3", "cases/validation/two_link_horizontal.yaml", oracle::unit_rods(2), 10.0},
      {"V4", "cases/validation/three_link.yaml", oracle::unit_rods(3), 5.0},
  };
  std::vector<ValidationRow> rows;
  for (const PendulumRun& run : runs) {
    const RunErrors errors = compare_run(run);
    const std::string subject = fmt::format("{} {} (compared to t = {:g} s)", run.id, run.case_path.substr(17), run.compare_until);
    rows.push_back({"K3", subject, "absolute angles [rad]", errors.angle, 1e-8});
    rows.push_back({"K3", subject, "pin reaction forces [N]", errors.reaction, 1e-6});
    rows.push_back({"K3", subject, "energy drift, relative", errors.energy_drift, 1e-9});
    if (run.id == "V1") {
      // T = 4 sqrt(L/g) K(sin(theta0/2)) for a point-mass pendulum released from theta0.
      const double theta0 = errors.first_angle.front();
      const double exact = 4.0 * std::sqrt(1.0 / g) * std::comp_ellint_1(std::sin(theta0 / 2.0));
      rows.push_back({"K3", subject, "period vs elliptic integral, relative",
                      std::abs(measured_period(errors) - exact) / exact, 1e-8});
    }
  }
  return rows;
}

}  // namespace heavesim::validation
