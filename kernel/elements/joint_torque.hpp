#pragma once
// A generalized force on one coordinate of a joint of the tree: a motor torque [N m]
// on a rotation coordinate, a force [N] on a translation coordinate, given as a
// function of time (the driving torque of Andrews' squeezing mechanism, Hairer &
// Wanner, Solving ODEs II, §VII.7; docs/physics/benchmarks.md). Its virtual work is
// tau(t) dq_k, so it adds tau(t) to the generalized force Q_k of that coordinate.
#include <functional>

#include "kernel/elements/force_element.hpp"

namespace heavesim {

class JointTorque : public ForceElement {
 public:
  /// tau(t): N m or N; must not allocate (it runs in the integrators' hot path).
  using TorqueFunction = std::function<double(double t)>;

  /// `velocity_index`: the coordinate's index in v (Joint::v_index + coordinate) of a
  /// joint whose coordinates are scalar (q and v line up: revolute, prismatic,
  /// cylindrical, universal). `depends_on_time`: whether tau varies with t (a constant
  /// torque lets the implicit forms skip the time column).
  JointTorque(std::string name, int velocity_index, TorqueFunction torque, bool depends_on_time)
      : name_(std::move(name)),
        velocity_index_(velocity_index),
        torque_(std::move(torque)),
        depends_on_time_(depends_on_time) {}

  const std::string& name() const override { return name_; }

  void apply(double t, const Model&, const Data&, Eigen::Ref<const VectorX>, AppliedForces& forces) const override {
    forces.joint_force[velocity_index_] += torque_(t);
  }

  /// Only the time, and only when tau(t) is not constant: the load is the same in every
  /// configuration and at every speed.
  ElementDependencies dependencies() const override { return {depends_on_time_, false, false, false, false}; }

  /// 0: a motor's torque is work put in from outside (a time-varying one is not even
  /// conservative), so the energy channels show it as a change of the total energy
  /// rather than as a stored potential.
  double potential_energy(const Model&, const Data&, Eigen::Ref<const VectorX>) const override { return 0.0; }

  /// The torque at time t [N m or N].
  double torque(double t) const { return torque_(t); }

 private:
  std::string name_;
  int velocity_index_ = 0;
  TorqueFunction torque_;
  bool depends_on_time_ = true;
};

}  // namespace heavesim
