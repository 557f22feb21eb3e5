#pragma once
// Torque-free rigid body in closed form.
//
// For a symmetric body (I1 = I2 about the CoM, symmetry axis e3 in body axes) the
// world angular momentum L is constant and, with w = L/I1 + beta n (n = R e3),
//   R(t) = exp([L]x t / I1) R0 exp([e3]x beta t),  beta = (1/I3 - 1/I1) (L . n0),
// which satisfies dR/dt = [w_world]x R exactly (Landau & Lifshitz, Mechanics, sec. 33).
// The symmetry axis precesses about L at the rate |L| / I1.
#include <Eigen/Geometry>

namespace heavesim::oracle {

class SymmetricTop {
 public:
  /// I1 = I2 (transverse) and I3 (axial) about the CoM [kg m^2]; initial orientation
  /// R0 (body -> world) and initial angular velocity in BODY axes [rad/s].
  SymmetricTop(double transverse_inertia, double axial_inertia, const Eigen::Matrix3d& R0,
               const Eigen::Vector3d& omega_body0);

  Eigen::Matrix3d orientation(double t) const;
  Eigen::Vector3d angular_momentum_world() const { return L_; }
  double precession_rate() const { return L_.norm() / I1_; }
  double kinetic_energy() const;

 private:
  double I1_, I3_;
  Eigen::Matrix3d R0_;
  Eigen::Vector3d omega_body0_, L_;
  double beta_;
};

}  // namespace heavesim::oracle
