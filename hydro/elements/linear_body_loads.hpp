#pragma once
// Linear and quadratic loads on one body's reference point (its body frame origin), in
// WAMIT order [surge, sway, heave, roll, pitch, yaw], world axes (body_motion.hpp):
//  * LinearRestoring: F = f0 - K xi, xi the small displacement from the reference pose
//    (linear hydrostatics with K = C and f0 = rho g V e_z; a linear mooring spring with
//    K the mooring stiffness and f0 the pretension). xi = [translation of the body
//    origin; rotation vector of R_world_body R_reference^T], world axes (body_motion.hpp):
//    for small rotations its angular part is [roll, pitch, yaw]; f0 is a constant world
//    vector, applied at the instantaneous body origin like K xi;
//  * BodyDamping: F = -B_lin v - diag(b_quad) v .* |v| (viscous hull damping, WEC-Sim's
//    linearDamping and quadDrag; docs/physics/hydrodynamics.md §9).
// Units: K in N/m, N, N m/rad blocks; B_lin in N s/m, N s, N m s/rad; b_quad in
// N s^2/m^2 (translations) and N m s^2/rad^2 (rotations). No allocation in apply().
#include "hydro/elements/body_motion.hpp"
#include "kernel/elements/evaluation_key.hpp"

namespace heavesim::hydro {

/// The gravitational part of WAMIT's "hydrostatic and gravitational" restoring matrix
/// (WAMIT User Manual v7, sec. 3.1): C44 = C55 = -m g z_G, C46 = m g x_G, C56 = m g y_G
/// [N m/rad], with the CG (x_G, y_G, z_G) [m] in the body frame (origin at the BEM
/// reference point). A .hst from a run given the CG includes it; the kernel applies the
/// weight m g at the CoM itself (exactly, for any rotation), so a LinearRestoring built
/// from such a .hst must use C - this (docs/physics/hydrodynamics.md §7: no double count).
inline Matrix6 wamit_gravitational_stiffness(double mass, const Vector3& center_of_mass, double gravity) {
  Matrix6 C = Matrix6::Zero();
  const double weight = mass * gravity;
  C(3, 3) = C(4, 4) = -weight * center_of_mass.z();
  C(3, 5) = weight * center_of_mass.x();
  C(4, 5) = weight * center_of_mass.y();
  return C;
}

class LinearRestoring : public ForceElement {
 public:
  LinearRestoring(std::string name, int link, const Matrix6& stiffness, const Vector6& constant_load,
                  const Transform& X_world_reference)
      : name_(std::move(name)), link_(link), stiffness_(stiffness), constant_load_(constant_load),
        reference_(X_world_reference) {}
  const std::string& name() const override { return name_; }
  void apply(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
             AppliedForces& forces) const override {
    const BodyMotion m = body_motion(model, data, link_);
    last_displacement_.keep(data, t, z, [&] { displacement_ = displacement(m.X_world_body, reference_); });
    const Vector6 load = constant_load_ - stiffness_ * displacement_;
    add_load(forces, link_, m.X_world_body.translation(), load);
  }
  /// The body's pose only.
  ElementDependencies dependencies() const override { return {false, true, false, false, false}; }
  /// V = xi^T K xi / 2 - f0 . xi [J], whose -dV/dxi is the load for a symmetric K (the
  /// small-motion potential; buoyancy's f0 . xi is the work against the constant
  /// buoyancy, the weight's own potential being the kernel's). The quadratic form sees
  /// only sym(K): the skew part of a K from which WAMIT's gravitational terms were taken
  /// out (C46, C56) does work that no potential holds, so the energy channel does not
  /// close by that much.
  /// At the pose apply() saw in this evaluation (a recorded sample's energy), its xi is
  /// read back (kernel/elements/evaluation_key.hpp); the pose depends on no time or state.
  double potential_energy(const Model& model, const Data& data, Eigen::Ref<const VectorX>) const override {
    const Vector6 xi = last_displacement_.same_stages(data)
                           ? displacement_
                           : displacement(body_motion(model, data, link_).X_world_body, reference_);
    return 0.5 * xi.dot(stiffness_ * xi) - constant_load_.dot(xi);
  }

 private:
  std::string name_;
  int link_;
  Matrix6 stiffness_;
  Vector6 constant_load_;
  Transform reference_;
  mutable EvaluationKey last_displacement_;  // where apply() computed displacement_
  mutable Vector6 displacement_ = Vector6::Zero();
};

class BodyDamping : public ForceElement {
 public:
  BodyDamping(std::string name, int link, const Matrix6& linear, const Vector6& quadratic = Vector6::Zero())
      : name_(std::move(name)), link_(link), linear_(linear), quadratic_(quadratic) {}
  const std::string& name() const override { return name_; }
  void apply(double, const Model& model, const Data& data, Eigen::Ref<const VectorX>,
             AppliedForces& forces) const override {
    const BodyMotion m = body_motion(model, data, link_);
    const Vector6 load = -linear_ * m.velocity - quadratic_.cwiseProduct(m.velocity.cwiseProduct(m.velocity.cwiseAbs()));
    add_load(forces, link_, m.X_world_body.translation(), load);
  }
  /// The body's pose (the reference point) and velocity.
  ElementDependencies dependencies() const override { return {false, true, true, false, false}; }

 private:
  std::string name_;
  int link_;
  Matrix6 linear_;
  Vector6 quadratic_;
};

}  // namespace heavesim::hydro
