#include "validation/oracles/planar_chain_oracle.hpp"

#include <cmath>

namespace heavesim::oracle {

std::vector<PlanarLink> unit_rods(int count) {
  return std::vector<PlanarLink>(count, PlanarLink{1.0, 1.0, 0.5, 1.0 / 12.0});
}

PlanarChainOracle::PlanarChainOracle(std::vector<PlanarLink> links, double gravity)
    : links_(std::move(links)), gravity_(gravity) {}

double PlanarChainOracle::ell(int j, int i) const {
  if (i < j) return links_[i].length;
  if (i == j) return links_[i].com;
  return 0.0;
}

Eigen::VectorXd PlanarChainOracle::accelerations(const Eigen::VectorXd& theta, const Eigen::VectorXd& theta_dot,
                                                 const Eigen::VectorXd& pin_torque) const {
  const int n = size();
  Eigen::MatrixXd M(n, n);
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n; ++i) {
    double gravity_moment = 0.0;
    for (int j = i; j < n; ++j) gravity_moment += links_[j].mass * ell(j, i);
    rhs[i] = -gravity_ * std::sin(theta[i]) * gravity_moment;
    rhs[i] += pin_torque[i] - (i + 1 < n ? pin_torque[i + 1] : 0.0);
    for (int k = 0; k < n; ++k) {
      double mu = 0.0;
      for (int j = std::max(i, k); j < n; ++j) mu += links_[j].mass * ell(j, i) * ell(j, k);
      M(i, k) = mu * std::cos(theta[i] - theta[k]) + (i == k ? links_[i].inertia : 0.0);
      rhs[i] -= mu * std::sin(theta[i] - theta[k]) * theta_dot[k] * theta_dot[k];
    }
  }
  return M.ldlt().solve(rhs);
}

Eigen::Matrix2Xd PlanarChainOracle::com_positions(const Eigen::VectorXd& theta) const {
  const int n = size();
  Eigen::Matrix2Xd r(2, n);
  for (int j = 0; j < n; ++j) {
    r.col(j).setZero();
    for (int k = 0; k <= j; ++k) r.col(j) += ell(j, k) * Eigen::Vector2d(-std::sin(theta[k]), -std::cos(theta[k]));
  }
  return r;
}

Eigen::Matrix2Xd PlanarChainOracle::pin_forces(const Eigen::VectorXd& theta, const Eigen::VectorXd& theta_dot,
                                               const Eigen::VectorXd& theta_ddot) const {
  const int n = size();
  // r_j'' = sum_k ell(j,k) [thdd_k u'(th_k) + thd_k^2 u''(th_k)], u = (-sin, -cos),
  // u' = (-cos, sin), u'' = (sin, cos).
  Eigen::Matrix2Xd com_acceleration(2, n);
  for (int j = 0; j < n; ++j) {
    com_acceleration.col(j).setZero();
    for (int k = 0; k <= j; ++k) {
      const double s = std::sin(theta[k]), c = std::cos(theta[k]);
      com_acceleration.col(j) += ell(j, k) * (theta_ddot[k] * Eigen::Vector2d(-c, s) +
                                              theta_dot[k] * theta_dot[k] * Eigen::Vector2d(s, c));
    }
  }
  const Eigen::Vector2d g(0.0, -gravity_);
  Eigen::Matrix2Xd force(2, n);
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int i = n - 1; i >= 0; --i) {
    sum += links_[i].mass * (com_acceleration.col(i) - g);
    force.col(i) = sum;
  }
  return force;
}

double PlanarChainOracle::energy(const Eigen::VectorXd& theta, const Eigen::VectorXd& theta_dot) const {
  const int n = size();
  const Eigen::Matrix2Xd r = com_positions(theta);
  double energy = 0.0;
  for (int j = 0; j < n; ++j) {
    Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
    for (int k = 0; k <= j; ++k)
      velocity += ell(j, k) * theta_dot[k] * Eigen::Vector2d(-std::cos(theta[k]), std::sin(theta[k]));
    energy += 0.5 * links_[j].mass * velocity.squaredNorm() + 0.5 * links_[j].inertia * theta_dot[j] * theta_dot[j];
    energy += links_[j].mass * gravity_ * r(1, j);
  }
  return energy;
}

}  // namespace heavesim::oracle
