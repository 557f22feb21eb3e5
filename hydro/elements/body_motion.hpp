#pragma once
// The motion of one body's reference point (its body frame origin) as the hydro force
// elements use it, in the seakeeping order of WAMIT: [surge, sway, heave, roll, pitch,
// yaw], world axes. Loads come back in the same order ([F; M about the reference
// point], N and N m, world axes) and are turned into the kernel's spatial force.
#include "kernel/model/data.hpp"
#include "kernel/elements/force_element.hpp"

namespace heavesim::hydro {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

struct BodyMotion {
  Transform X_world_body;  // pose of the body frame in the world
  Vector6 velocity;        // [v of the reference point (m/s); omega (rad/s)], world axes
};

inline BodyMotion body_motion(const Model& model, const Data& data, int link) {
  BodyMotion m;
  m.X_world_body = data.X_world_link[link] * model.links[link].X_link_body;
  const Motion& v = data.velocity_world[link];
  m.velocity << v.point_velocity(m.X_world_body.translation()), v.angular();
  return m;
}

/// Small-motion displacement [x, y, z (m); rotation vector (rad)] of the body frame
/// from X_reference, world axes (the rotation vector is exact for any rotation; the
/// linear coefficients that multiply it are meant for small ones).
inline Vector6 displacement(const Transform& X_world_body, const Transform& X_reference) {
  Vector6 xi;
  const Eigen::AngleAxisd rotation(X_world_body.rotation() * X_reference.rotation().transpose());
  xi << X_world_body.translation() - X_reference.translation(), rotation.angle() * rotation.axis();
  return xi;
}

/// Adds load = [F; M about point_world] (world axes) on `link` to the applied forces.
inline void add_load(AppliedForces& forces, int link, const Vector3& point_world, const Vector6& load) {
  const Vector3 f = load.head<3>();
  forces.external_force_world[link] += Force(load.tail<3>() + point_world.cross(f), f);
}

}  // namespace heavesim::hydro
