// K2: planar chains of n = 2, 3, 5 uniform rods at 1000 random states against the
// n-link oracle of docs/physics/multibody.md §9 (absolute angles, Lagrange form).
#include <random>

#include <fmt/format.h>

#include "kernel/algorithms/forward_dynamics.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "samples/planar_chains.hpp"
#include "validation/checks/relative_error.hpp"
#include "validation/checks/validation_suite.hpp"
#include "validation/oracles/planar_chain_oracle.hpp"

namespace heavesim::validation {
namespace {

/// The oracle's link data as the sample library's (the same four numbers).
std::vector<samples::PlanarLink> sample_links(const std::vector<oracle::PlanarLink>& links) {
  std::vector<samples::PlanarLink> converted;
  for (const oracle::PlanarLink& link : links) converted.push_back({link.length, link.mass, link.com, link.inertia});
  return converted;
}

}  // namespace

std::vector<ValidationRow> check_k2_planar_chains() {
  std::vector<ValidationRow> rows;
  for (int n : {2, 3, 5}) {
    const std::vector<oracle::PlanarLink> rods = oracle::unit_rods(n);
    const oracle::PlanarChainOracle reference(rods);
    const Model model = samples::planar_chain(sample_links(rods));
    Data data(model);
    std::mt19937_64 random(1000 + n);
    std::uniform_real_distribution<double> angle(-M_PI, M_PI), rate(-5.0, 5.0), torque(-10.0, 10.0);
    double qdd_error = 0.0, reaction_error = 0.0;
    for (int sample = 0; sample < 1000; ++sample) {
      VectorX q(n), qd(n), tau(n);
      for (int i = 0; i < n; ++i) {
        q[i] = angle(random);
        qd[i] = rate(random);
        tau[i] = torque(random);
      }
      const VectorX theta = samples::absolute_from_relative(q), theta_dot = samples::absolute_from_relative(qd);
      const VectorX theta_ddot = reference.accelerations(theta, theta_dot, tau);
      const Eigen::Matrix2Xd pin_force = reference.pin_forces(theta, theta_dot, theta_ddot);

      update_positions(model, data, q);
      update_velocities(model, data, q, qd);
      const VectorX qdd = articulated_body_forward_dynamics(model, data, tau);
      qdd_error = std::max(qdd_error, relative_error(samples::absolute_from_relative(qdd), theta_ddot));
      compute_joint_wrenches(model, data);
      for (int i = 0; i < n; ++i) {
        const Vector3 force = joint_reaction(model, data, i + 1).force_world;
        const Vector3 expected(pin_force(0, i), 0.0, pin_force(1, i));
        reaction_error = std::max(reaction_error, relative_error(force, expected));
      }
    }
    const std::string subject = fmt::format("{}-link planar rods, 1000 random states", n);
    rows.push_back({"K2", subject, "absolute angular accelerations, relative", qdd_error, 1e-12});
    rows.push_back({"K2", subject, "pin reaction forces, relative", reaction_error, 1e-12});
  }
  return rows;
}

}  // namespace heavesim::validation
