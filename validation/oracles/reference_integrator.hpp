#pragma once
// High-accuracy reference integration for the oracles: SUNDIALS ARKODE explicit
// Fehlberg 8(7) called directly (not through the kernel's integrator classes), so a
// reference shares neither coordinates nor integration code with the kernel.
#include <Eigen/Core>
#include <functional>
#include <vector>

namespace heavesim::oracle {

using Rhs = std::function<void(double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot)>;

/// y at each time in `times` (ascending, first >= t0) for dy/dt = rhs(t, y), y(t0) = y0.
std::vector<Eigen::VectorXd> integrate_reference(const Rhs& rhs, double t0, const Eigen::VectorXd& y0,
                                                 const std::vector<double>& times, double relative_tolerance,
                                                 double absolute_tolerance);

}  // namespace heavesim::oracle
