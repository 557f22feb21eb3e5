// K1: double pendulum, 1000 random (q, qd, tau): accelerations by ABA and by CRBA and
// the two pin reactions against the textbook closed form (validation/oracles).
#include <random>

#include "kernel/algorithms/forward_dynamics.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "samples/planar_chains.hpp"
#include "validation/checks/relative_error.hpp"
#include "validation/checks/validation_suite.hpp"
#include "validation/oracles/double_pendulum_closed_form.hpp"

namespace heavesim::validation {

std::vector<ValidationRow> check_k1_double_pendulum() {
  // Deliberately unequal links so that no term hides behind a symmetry.
  const oracle::DoublePendulumParameters p{1.3, 0.7, 1.1, 0.45, 0.6, 0.11, 0.05, g};
  const Model model = samples::planar_chain({{p.L1, p.m1, p.a1, p.I1}, {1.0, p.m2, p.a2, p.I2}}, p.g);
  Data data(model);
  std::mt19937_64 random(20261122);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), rate(-6.0, 6.0), torque(-20.0, 20.0);

  double qdd_aba = 0.0, qdd_crba = 0.0, pin1 = 0.0, pin2 = 0.0, moments = 0.0;
  for (int sample = 0; sample < 1000; ++sample) {
    const Eigen::Vector2d q(angle(random), angle(random)), qd(rate(random), rate(random)),
        tau(torque(random), torque(random));
    const oracle::DoublePendulumSolution reference = oracle::solve_double_pendulum(p, q, qd, tau);

    update_positions(model, data, q);
    update_velocities(model, data, q, qd);
    qdd_crba = std::max(qdd_crba, relative_error(composite_rigid_body_forward_dynamics(model, data, tau), reference.qdd));
    qdd_aba = std::max(qdd_aba, relative_error(articulated_body_forward_dynamics(model, data, tau), reference.qdd));
    compute_joint_wrenches(model, data);
    const JointReaction r1 = joint_reaction(model, data, 1), r2 = joint_reaction(model, data, 2);
    pin1 = std::max(pin1, relative_error(Eigen::Vector2d(r1.force_world.x(), r1.force_world.z()), reference.pin1_force) +
                              std::abs(r1.force_world.y()) / reference.pin1_force.norm());
    pin2 = std::max(pin2, relative_error(Eigen::Vector2d(r2.force_world.x(), r2.force_world.z()), reference.pin2_force) +
                              std::abs(r2.force_world.y()) / reference.pin2_force.norm());
    // A passive planar pin transmits no moment except the applied torque about +Y.
    const double moment_scale = std::max(tau.norm(), reference.pin1_force.norm() * p.L1);
    moments = std::max(moments, ((r1.moment_world - Vector3(0.0, tau[0], 0.0)).norm() +
                                 (r2.moment_world - Vector3(0.0, tau[1], 0.0)).norm()) /
                                    moment_scale);
  }
  const std::string subject = "double pendulum, 1000 random states";
  return {{"K1", subject, "qdd by ABA, relative", qdd_aba, 1e-12},
          {"K1", subject, "qdd by CRBA + Cholesky, relative", qdd_crba, 1e-12},
          {"K1", subject, "pin 1 reaction force, relative", pin1, 1e-12},
          {"K1", subject, "pin 2 reaction force, relative", pin2, 1e-12},
          {"K1", subject, "pin reaction moments, relative", moments, 1e-12}};
}

}  // namespace heavesim::validation
