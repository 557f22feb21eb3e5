// K5: torque-free rigid body. Conservation of linear momentum, angular momentum about
// the world origin and kinetic energy over 100 s for an asymmetric body with an
// offset centre of mass; and a symmetric top against its closed-form motion
// (validation/oracles/symmetric_top).
#include <cmath>

#include "kernel/algorithms/energy.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "validation/checks/validation_suite.hpp"
#include "validation/oracles/symmetric_top.hpp"

namespace heavesim::validation {
namespace {

double unwrap_step(double previous, double current) {
  double delta = current - previous;
  while (delta > M_PI) delta -= 2 * M_PI;
  while (delta < -M_PI) delta += 2 * M_PI;
  return delta;
}

}  // namespace

std::vector<ValidationRow> check_k5_free_body() {
  std::vector<ValidationRow> rows;
  {
    Vector6 momentum0 = Vector6::Zero();
    double energy0 = 0.0, linear_error = 0.0, angular_error = 0.0, energy_error = 0.0;
    bool first = true;
    run_case("cases/validation/free_body.yaml", {}, [&](double, const MultibodySystem& system) {
      // Spatial momentum h = I v about the world origin: [angular momentum; linear momentum].
      const Vector6 h = link_momentum(system.model(), system.data(), 1, system.data().velocity_world[1]).vector();
      const double energy = kinetic_energy(system.model(), system.data());
      if (first) {
        momentum0 = h;
        energy0 = energy;
        first = false;
      }
      linear_error = std::max(linear_error, (h.tail<3>() - momentum0.tail<3>()).norm() / momentum0.tail<3>().norm());
      angular_error = std::max(angular_error, (h.head<3>() - momentum0.head<3>()).norm() / momentum0.head<3>().norm());
      energy_error = std::max(energy_error, std::abs(energy - energy0) / energy0);
    });
    const std::string subject = "asymmetric free body, offset CoM, 100 s";
    rows.push_back({"K5", subject, "linear momentum, relative", linear_error, 1e-10});
    rows.push_back({"K5", subject, "angular momentum about the origin, relative", angular_error, 1e-10});
    rows.push_back({"K5", subject, "kinetic energy, relative", energy_error, 1e-10});
  }
  {
    std::optional<oracle::SymmetricTop> top;
    double orientation_error = 0.0, swept_angle = 0.0, previous_angle = 0.0, last_time = 0.0;
    Eigen::Vector3d L_unit, e1, e2;
    run_case("cases/validation/symmetric_top.yaml", {}, [&](double t, const MultibodySystem& system) {
      const Transform X_world_body = system.data().X_world_link[1] * system.model().links[1].X_link_body;
      const Matrix3& R = X_world_body.rotation();
      if (!top) {
        const Matrix3 inertia = system.model().links[1].inertia.inertia_com();
        const Vector3 omega_body = R.transpose() * system.data().velocity_world[1].angular();
        top.emplace(inertia(0, 0), inertia(2, 2), R, omega_body);
        L_unit = top->angular_momentum_world().normalized();
        e1 = L_unit.unitOrthogonal();
        e2 = L_unit.cross(e1);
      }
      orientation_error = std::max(orientation_error, (R - top->orientation(t)).cwiseAbs().maxCoeff());
      // The symmetry axis n = R e3 circles about L: accumulate the swept azimuth.
      const Vector3 n = R.col(2);
      const double azimuth = std::atan2(n.dot(e2), n.dot(e1));
      if (t > 0.0) swept_angle += unwrap_step(previous_angle, azimuth);
      previous_angle = azimuth;
      last_time = t;
    });
    const double measured_rate = swept_angle / last_time;
    const std::string subject = "symmetric top, 100 s";
    rows.push_back({"K5", subject, "orientation vs closed form (max matrix entry)", orientation_error, 1e-10});
    rows.push_back({"K5", subject, "precession rate |L|/I1, relative",
                    std::abs(measured_rate - top->precession_rate()) / top->precession_rate(), 1e-10});
  }
  return rows;
}

}  // namespace heavesim::validation
