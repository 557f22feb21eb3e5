#pragma once
// Exact equations of a planar chain of links hanging from a ground pin, in ABSOLUTE
// angles theta_i (from the downward vertical, positive counter-clockwise about +Y),
// written from the Lagrangian directly (docs/physics/multibody.md §9). Independent of
// the kernel: no spatial algebra, different coordinates.
//
// Link i: pin-to-pin length L_i, mass m_i, CoM at distance a_i from its upper pin,
// inertia I_i about the CoM (axis Y). ell(j, i) = L_i if i < j, a_i if i = j, 0 if i > j;
// mu_ik = sum_{j >= max(i,k)} m_j ell(j,i) ell(j,k):
//   sum_k [mu_ik cos(th_i - th_k) + delta_ik I_i] thdd_k
//     + sum_k mu_ik sin(th_i - th_k) thd_k^2 + g sin th_i sum_j m_j ell(j,i) = Q_i,
// with Q_i = tau_i - tau_{i+1} for torques tau_k acting at pin k (parent on child).
#include <Eigen/Dense>
#include <vector>

namespace heavesim::oracle {

struct PlanarLink {
  double length;   // m, pin to pin
  double mass;     // kg
  double com;      // m, CoM distance from the upper pin
  double inertia;  // kg m^2, about the CoM
};

/// Uniform slender rods of length 1 m and mass 1 kg (the validation set's links).
std::vector<PlanarLink> unit_rods(int count);

class PlanarChainOracle {
 public:
  explicit PlanarChainOracle(std::vector<PlanarLink> links, double gravity = 9.81);

  int size() const { return static_cast<int>(links_.size()); }

  /// Absolute angular accelerations for absolute angles/rates and pin torques.
  Eigen::VectorXd accelerations(const Eigen::VectorXd& theta, const Eigen::VectorXd& theta_dot,
                                const Eigen::VectorXd& pin_torque) const;

  /// Force [N] on link i from its parent at pin i, world (x, z), for the state and
  /// accelerations: F_i = sum_{j >= i} m_j (r_j'' - g).
  Eigen::Matrix2Xd pin_forces(const Eigen::VectorXd& theta, const Eigen::VectorXd& theta_dot,
                              const Eigen::VectorXd& theta_ddot) const;

  /// CoM positions (x, z) [m] with the top pin at the origin; link hangs along
  /// (-sin theta, -cos theta) (rotation about +Y).
  Eigen::Matrix2Xd com_positions(const Eigen::VectorXd& theta) const;

  /// Kinetic plus gravitational potential energy [J].
  double energy(const Eigen::VectorXd& theta, const Eigen::VectorXd& theta_dot) const;

 private:
  double ell(int j, int i) const;
  std::vector<PlanarLink> links_;
  double gravity_;
};

}  // namespace heavesim::oracle
