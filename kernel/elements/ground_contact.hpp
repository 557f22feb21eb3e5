#pragma once
// A body point pressing on an earth-fixed horizontal surface z = z_s (world frame, z
// up): a unilateral spring-damper, the drill bit on the formation of docs/physics/
// drilling-rig.md §2 (k_f = 5e7 N/m, c_f = 5e5 N s/m). With the penetration d = z_s - z_p [m] and
// its rate dd/dt = -v_z [m/s], the surface pushes the point up with
//   F = max(0, k d + c dd/dt)   for d > 0,   F = 0 otherwise
// (a formation cannot pull the bit back: the damper only resists while the force stays
// compressive, Hunt-Crossley's no-adhesion clamp). F is the weight on bit (WOB).
// Channels: force (WOB) [N] and penetration [m].
#include <algorithm>

#include "kernel/elements/body_point.hpp"
#include "kernel/elements/force_element.hpp"

namespace heavesim {

struct GroundContactParameters {
  double stiffness = 0.0;       // k [N/m], > 0
  double damping = 0.0;         // c [N s/m], >= 0
  double surface_height = 0.0;  // z_s [m], world frame
};

class GroundContact : public ForceElement {
 public:
  GroundContact(std::string name, BodyPoint point, GroundContactParameters parameters)
      : name_(std::move(name)), point_(point), parameters_(parameters) {
    channels_ = {{"force", "N", "contact force pushing the point up, world +z (weight on bit); 0 when lifted off"},
                 {"penetration", "m", "depth of the point below the contact surface, > 0 in contact"}};
  }
  const std::string& name() const override { return name_; }

  struct State {
    Vector3 position;    // m, the point, world frame
    double penetration;  // m
    double force;        // N, >= 0, upward on the point
  };
  State state(const Data& data) const {
    const Vector3 p = point_.position_world(data);  // once: the rate and the load need it too
    const double penetration = parameters_.surface_height - p.z();
    if (penetration <= 0.0) return {p, penetration, 0.0};
    const double rate = -data.velocity_world[point_.link].point_velocity(p).z();
    return {p, penetration, std::max(0.0, parameters_.stiffness * penetration + parameters_.damping * rate)};
  }

  void apply(double, const Model&, const Data& data, Eigen::Ref<const VectorX>, AppliedForces& forces) const override {
    const State s = state(data);
    if (s.force > 0.0) forces.add_force_at_point(point_.link, s.position, Vector3(0.0, 0.0, s.force));
  }
  /// The point's place and velocity.
  ElementDependencies dependencies() const override { return {false, true, true, false, false}; }
  /// V = k d^2 / 2 [J] while the point penetrates (d > 0), 0 when lifted off: the
  /// spring part of the contact (the damper stores nothing).
  double potential_energy(const Model&, const Data& data, Eigen::Ref<const VectorX>) const override {
    const double penetration = parameters_.surface_height - point_.position_world(data).z();
    return penetration > 0.0 ? 0.5 * parameters_.stiffness * penetration * penetration : 0.0;
  }
  const std::vector<ElementChannel>& channels() const override { return channels_; }
  void outputs(double, const Model&, const Data& data, Eigen::Ref<const VectorX>, std::span<double> values) const override {
    const State s = state(data);
    values[0] = s.force;
    values[1] = s.penetration;
  }

 private:
  std::string name_;
  BodyPoint point_;
  GroundContactParameters parameters_;
  std::vector<ElementChannel> channels_;
};

}  // namespace heavesim
