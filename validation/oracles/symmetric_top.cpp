#include "validation/oracles/symmetric_top.hpp"

namespace heavesim::oracle {

SymmetricTop::SymmetricTop(double transverse_inertia, double axial_inertia, const Eigen::Matrix3d& R0,
                           const Eigen::Vector3d& omega_body0)
    : I1_(transverse_inertia), I3_(axial_inertia), R0_(R0), omega_body0_(omega_body0) {
  const Eigen::Vector3d L_body(I1_ * omega_body0.x(), I1_ * omega_body0.y(), I3_ * omega_body0.z());
  L_ = R0 * L_body;
  beta_ = (1.0 / I3_ - 1.0 / I1_) * L_body.z();
}

Eigen::Matrix3d SymmetricTop::orientation(double t) const {
  const double L_norm = L_.norm();
  const Eigen::Matrix3d precession =
      L_norm > 0.0 ? Eigen::AngleAxisd(L_norm * t / I1_, L_ / L_norm).toRotationMatrix() : Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d spin = Eigen::AngleAxisd(beta_ * t, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return precession * R0_ * spin;
}

double SymmetricTop::kinetic_energy() const {
  return 0.5 * (I1_ * (omega_body0_.x() * omega_body0_.x() + omega_body0_.y() * omega_body0_.y()) +
                I3_ * omega_body0_.z() * omega_body0_.z());
}

}  // namespace heavesim::oracle
