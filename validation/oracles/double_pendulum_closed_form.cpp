#include "validation/oracles/double_pendulum_closed_form.hpp"

#include <cmath>

namespace heavesim::oracle {

DoublePendulumSolution solve_double_pendulum(const DoublePendulumParameters& p, const Eigen::Vector2d& q,
                                             const Eigen::Vector2d& qd, const Eigen::Vector2d& tau) {
  const double c2 = std::cos(q[1]), s2 = std::sin(q[1]);
  const double phi1 = q[0], phi2 = q[0] + q[1];
  // M(q) in relative coordinates (e.g. Spong, Robot Modeling and Control, eq. 7.87).
  const double h = p.m2 * p.L1 * p.a2;
  const double M11 = p.I1 + p.m1 * p.a1 * p.a1 + p.I2 + p.m2 * (p.L1 * p.L1 + p.a2 * p.a2) + 2.0 * h * c2;
  const double M12 = p.I2 + p.m2 * p.a2 * p.a2 + h * c2;
  const double M22 = p.I2 + p.m2 * p.a2 * p.a2;
  // Coriolis/centrifugal: C1 = -h s2 (2 qd1 qd2 + qd2^2), C2 = h s2 qd1^2.
  const double C1 = -h * s2 * (2.0 * qd[0] * qd[1] + qd[1] * qd[1]);
  const double C2 = h * s2 * qd[0] * qd[0];
  // Gravity with the links hanging along -cos: G = dV/dq, V = -g(m1 a1 cos phi1 + m2(L1 cos phi1 + a2 cos phi2)).
  const double G1 = p.g * ((p.m1 * p.a1 + p.m2 * p.L1) * std::sin(phi1) + p.m2 * p.a2 * std::sin(phi2));
  const double G2 = p.g * p.m2 * p.a2 * std::sin(phi2);
  Eigen::Matrix2d M;
  M << M11, M12, M12, M22;
  DoublePendulumSolution solution;
  solution.qdd = M.inverse() * (tau - Eigen::Vector2d(C1 + G1, C2 + G2));

  // CoM accelerations from r1 = a1 u(phi1), r2 = L1 u(phi1) + a2 u(phi2),
  // u = (-sin, -cos), u' = (-cos, sin), u'' = (sin, cos).
  const double phi1_d = qd[0], phi2_d = qd[0] + qd[1];
  const double phi1_dd = solution.qdd[0], phi2_dd = solution.qdd[0] + solution.qdd[1];
  auto du = [](double phi) { return Eigen::Vector2d(-std::cos(phi), std::sin(phi)); };
  auto ddu = [](double phi) { return Eigen::Vector2d(std::sin(phi), std::cos(phi)); };
  const Eigen::Vector2d a_link1 = p.a1 * (phi1_dd * du(phi1) + phi1_d * phi1_d * ddu(phi1));
  const Eigen::Vector2d a_elbow = p.L1 * (phi1_dd * du(phi1) + phi1_d * phi1_d * ddu(phi1));
  const Eigen::Vector2d a_link2 = a_elbow + p.a2 * (phi2_dd * du(phi2) + phi2_d * phi2_d * ddu(phi2));
  const Eigen::Vector2d g(0.0, -p.g);
  solution.pin2_force = p.m2 * (a_link2 - g);
  solution.pin1_force = p.m1 * (a_link1 - g) + solution.pin2_force;
  return solution;
}

}  // namespace heavesim::oracle
