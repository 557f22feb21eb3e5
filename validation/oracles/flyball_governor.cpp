#include "validation/oracles/flyball_governor.hpp"

#include <cmath>

#include "validation/oracles/reference_integrator.hpp"

namespace heavesim::oracle {

namespace {

// Moments of inertia of one rod about its centre: along it (a square section) and across it.
double rod_axial_inertia(const FlyballGovernorParameters& p) {
  return p.rod_mass * 2.0 * p.rod_section * p.rod_section / 12.0;
}
double rod_transverse_inertia(const FlyballGovernorParameters& p) {
  return p.rod_mass * (p.rod_length * p.rod_length + p.rod_section * p.rod_section) / 12.0;
}

// J(theta) and dJ/dtheta: the moment of inertia of everything about the shaft axis.
void axial_inertia(const FlyballGovernorParameters& p, double theta, double& inertia, double& derivative) {
  const double sine = std::sin(theta), cosine = std::cos(theta);
  const double centre = 0.5 * p.rod_length;
  const double rod_radius = p.pin_offset + centre * cosine;
  const double ball_radius = p.pin_offset + p.rod_length * cosine;
  const double axial = rod_axial_inertia(p), transverse = rod_transverse_inertia(p);
  inertia = p.shaft_axial_inertia + p.slider_axial_inertia +
            2.0 * (axial * sine * sine + transverse * cosine * cosine + p.rod_mass * rod_radius * rod_radius +
                   p.ball_mass * ball_radius * ball_radius);
  derivative = 2.0 * (2.0 * (axial - transverse) * sine * cosine - 2.0 * p.rod_mass * rod_radius * centre * sine -
                      2.0 * p.ball_mass * ball_radius * p.rod_length * sine);
}

}  // namespace

std::vector<FlyballGovernorState> flyball_governor_states(const FlyballGovernorParameters& p,
                                                          const std::vector<double>& times, double tolerance) {
  double initial_inertia = 0.0, unused = 0.0;
  axial_inertia(p, p.theta0, initial_inertia, unused);
  const double angular_momentum = initial_inertia * p.spin_rate0;  // kg m^2/s about the shaft, conserved
  const double centre = 0.5 * p.rod_length;
  const double arm_inertia =
      2.0 * (rod_transverse_inertia(p) + p.rod_mass * centre * centre + p.ball_mass * p.rod_length * p.rod_length);
  const double arm_first_moment = p.rod_mass * centre + p.ball_mass * p.rod_length;

  const Rhs rhs = [=](double, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
    const double theta = y[0], theta_rate = y[1], height = y[2], height_rate = y[3];
    double inertia = 0.0, inertia_derivative = 0.0;
    axial_inertia(p, theta, inertia, inertia_derivative);
    const double spin_rate = angular_momentum / inertia;
    // The spring-damper in the arms' plane: from (e, s) on the slider to the rod's centre.
    const double dx = centre * std::cos(theta);
    const double dz = p.pin_height - centre * std::sin(theta) - height;
    const double length = std::hypot(dx, dz);
    const double length_dtheta = (dx * (-centre * std::sin(theta)) + dz * (-centre * std::cos(theta))) / length;
    const double length_ds = -dz / length;
    const double length_rate = length_dtheta * theta_rate + length_ds * height_rate;
    const double tension = p.stiffness * (length - p.rest_length) + p.damping * length_rate;
    ydot[0] = theta_rate;
    ydot[1] = (0.5 * inertia_derivative * spin_rate * spin_rate + 2.0 * p.gravity * std::cos(theta) * arm_first_moment -
               2.0 * tension * length_dtheta) /
              arm_inertia;
    ydot[2] = height_rate;
    ydot[3] = (-p.slider_mass * p.gravity - 2.0 * tension * length_ds) / p.slider_mass;
  };
  Eigen::VectorXd initial(4);
  initial << p.theta0, 0.0, p.slider_height0, 0.0;
  const std::vector<Eigen::VectorXd> states = integrate_reference(rhs, 0.0, initial, times, tolerance, tolerance);
  std::vector<FlyballGovernorState> result;
  result.reserve(states.size());
  for (const Eigen::VectorXd& state : states) {
    double inertia = 0.0, unused_derivative = 0.0;
    axial_inertia(p, state[0], inertia, unused_derivative);
    result.push_back({state[0], state[1], state[2], state[3], angular_momentum / inertia});
  }
  return result;
}

}  // namespace heavesim::oracle
