#include "validation/oracles/four_bar_parallelogram.hpp"

#include <cmath>

#include "validation/oracles/reference_integrator.hpp"

namespace heavesim::oracle {

std::vector<double> four_bar_crank_angles(int windows, double gravity, const std::vector<double>& times,
                                          double tolerance) {
  const double n = windows;
  const double ratio = ((n + 1.0) / 2.0 + n) / ((n + 1.0) / 3.0 + n);
  const Rhs rhs = [=](double, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
    ydot[0] = y[1];
    ydot[1] = gravity * std::sin(y[0]) * ratio;
  };
  const std::vector<Eigen::VectorXd> states =
      integrate_reference(rhs, 0.0, Eigen::Vector2d(0.0, 1.0), times, tolerance, tolerance);
  std::vector<double> angles;
  for (const Eigen::VectorXd& state : states) angles.push_back(state[0]);
  return angles;
}

std::vector<double> parallelogram_crank_angles(double first_moment, double second_moment, double gravity,
                                               double q0, double rate0, const std::vector<double>& times,
                                               double tolerance) {
  const double ratio = gravity * first_moment / second_moment;  // 1/s^2
  const Rhs rhs = [=](double, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
    ydot[0] = y[1];
    ydot[1] = -ratio * std::sin(y[0]);
  };
  const std::vector<Eigen::VectorXd> states =
      integrate_reference(rhs, 0.0, Eigen::Vector2d(q0, rate0), times, tolerance, tolerance);
  std::vector<double> angles;
  angles.reserve(states.size());
  for (const Eigen::VectorXd& state : states) angles.push_back(state[0]);
  return angles;
}

}  // namespace heavesim::oracle
