#pragma once
// A linear spring-damper between two body points (a strut, a drilling line, the
// spring of SUNDIALS' slider-crank example). Tension T = k (l - l0) + c dl/dt [N]
// pulls the points together along the line joining them.
#include "kernel/elements/body_point.hpp"
#include "kernel/elements/force_element.hpp"

namespace heavesim {

struct SpringDamperParameters {
  double stiffness = 0.0;    // N/m, >= 0
  double damping = 0.0;      // N s/m, >= 0
  double rest_length = 0.0;  // m, >= 0
};

class SpringDamper : public ForceElement {
 public:
  SpringDamper(std::string name, BodyPoint a, BodyPoint b, SpringDamperParameters parameters)
      : name_(std::move(name)), a_(a), b_(b), parameters_(parameters) {}
  const std::string& name() const override { return name_; }
  void apply(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
             AppliedForces& forces) const override;
  /// The end points' places and velocities.
  ElementDependencies dependencies() const override { return {false, true, true, false, false}; }
  /// V = k (l - l0)^2 / 2 [J].
  double potential_energy(const Model& model, const Data& data, Eigen::Ref<const VectorX> z) const override;
  /// Length [m], its rate [m/s] and the tension [N] at the current stages.
  struct State {
    double length, length_rate, tension;
  };
  State state(const Data& data) const;

 private:
  /// The state for end points already placed (pa, pb in the world frame [m]).
  State state_at(const Vector3& pa, const Vector3& pb, const Data& data) const;

  std::string name_;
  BodyPoint a_, b_;
  SpringDamperParameters parameters_;
};

}  // namespace heavesim
