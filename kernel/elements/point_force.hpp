#pragma once
// A force of fixed world direction and magnitude on a body point (a hook load, the
// push of SUNDIALS' slider-crank example).
#include "kernel/elements/body_point.hpp"
#include "kernel/elements/force_element.hpp"

namespace heavesim {

class PointForce : public ForceElement {
 public:
  PointForce(std::string name, BodyPoint point, const Vector3& force_world)
      : name_(std::move(name)), point_(point), force_world_(force_world) {}
  const std::string& name() const override { return name_; }
  void apply(double, const Model&, const Data& data, Eigen::Ref<const VectorX>, AppliedForces& forces) const override {
    forces.add_force_at_point(point_.link, point_.position_world(data), force_world_);
  }
  /// The point's place (the moment about the world origin).
  ElementDependencies dependencies() const override { return {false, true, false, false, false}; }
  /// A constant world force is conservative: V = -F . p_world [J], p the point's world
  /// position (zero where the point is at the world origin).
  double potential_energy(const Model&, const Data& data, Eigen::Ref<const VectorX>) const override {
    return -force_world_.dot(point_.position_world(data));
  }

 private:
  std::string name_;
  BodyPoint point_;
  Vector3 force_world_;  // N, world frame
};

}  // namespace heavesim
