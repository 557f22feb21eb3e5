#include "control/stroke/stroke_axis.hpp"

#include "kernel/joints/joint.hpp"
#include "kernel/parameter_error.hpp"

namespace heavesim {

StrokeAxis StrokeAxis::on_joint(const Model& model, int joint_index, double mid_stroke) {
  // The stroke is the joint's one coordinate, along its axis.
  if (joint_index < 1 || joint_index >= model.num_links())
    throw ParameterError("joint", "joint index " + std::to_string(joint_index) + ", which is not a joint",
                         "the name of a prismatic joint (the stroke is its coordinate)");
  const Joint& joint = model.joints[joint_index];
  if (!std::holds_alternative<PrismaticJoint>(joint.type))
    throw ParameterError("joint", "'" + joint.name + "', a " + joint_type_name(joint.type) + " joint",
                         "the name of a prismatic joint (the stroke is its coordinate)");
  StrokeAxis axis;
  axis.joint = joint_index;
  axis.mid_stroke = mid_stroke;
  return axis;
}

StrokeAxis StrokeAxis::between(const Model& model, const BodyPoint& base, const BodyPoint& moving,
                               const Vector3& axis_base_body, double mid_stroke) {
  StrokeAxis axis;
  axis.base = base;
  axis.moving = moving;
  // Body frame -> link frame (the link frame is the canonical joint frame, see model.hpp).
  axis.axis_base_link = base.link == 0 ? axis_base_body
                                       : Vector3(model.links[base.link].X_link_body.rotation() * axis_base_body);
  axis.mid_stroke = mid_stroke;
  return axis;
}

namespace {

/// The prismatic joint's parent-side frame in the world: X_world_parentlink * placement.
Transform parent_joint_frame(const Model& model, const Data& data, int joint) {
  return data.X_world_link[model.joints[joint].parent] * model.joints[joint].placement;
}

}  // namespace

StrokeMotion stroke_motion(const StrokeAxis& axis, const Model& model, const Data& data) {
  if (axis.joint_form()) {
    // The child link frame is the parent-side joint frame moved by q along its z axis
    // (PrismaticJoint::place), and v_child - v_parent = S qdot with S = [0; z_world].
    const int i = axis.joint;
    const Vector3 z_world = data.X_world_link[i].rotation().col(2);
    const Vector3 offset = data.X_world_link[i].translation() - parent_joint_frame(model, data, i).translation();
    const Motion relative = data.velocity_world[i] - data.velocity_world[model.joints[i].parent];
    return {z_world.dot(offset) - axis.mid_stroke, z_world.dot(relative.linear())};
  }
  const Vector3 axis_world = data.X_world_link[axis.base.link].rotation() * axis.axis_base_link;
  const Vector3 base_point = axis.base.position_world(data);
  const Vector3 moving_point = axis.moving.position_world(data);
  // d/dt [a . (p_m - p_b)] = a . (v_m(p_m) - v_base_body(p_m)): the rate at which the
  // moving point leaves the base body along the axis (the axis turns with the base).
  const Vector3 relative_velocity = data.velocity_world[axis.moving.link].point_velocity(moving_point) -
                                    data.velocity_world[axis.base.link].point_velocity(moving_point);
  return {axis_world.dot(moving_point - base_point) - axis.mid_stroke, axis_world.dot(relative_velocity)};
}

void apply_stroke_force(const StrokeAxis& axis, const Model& model, const Data& data, double force,
                        AppliedForces& forces) {
  if (axis.joint_form()) {
    forces.joint_force[model.joints[axis.joint].v_index] += force;
    return;
  }
  // Both halves of the pair act at the moving point: no spurious moment, and their
  // power is exactly force * ds/dt (stroke_motion).
  const Vector3 axis_world = data.X_world_link[axis.base.link].rotation() * axis.axis_base_link;
  const Vector3 moving_point = axis.moving.position_world(data);
  forces.add_force_at_point(axis.moving.link, moving_point, force * axis_world);
  forces.add_force_at_point(axis.base.link, moving_point, -force * axis_world);
}

BaseMotion base_motion(const StrokeAxis& axis, const Model& model, const Data& data) {
  if (axis.joint_form()) {
    const int parent = model.joints[axis.joint].parent;
    const Transform frame = parent_joint_frame(model, data, axis.joint);
    return {frame.translation(), data.velocity_world[parent].point_velocity(frame.translation()),
            frame.rotation().col(2)};
  }
  const Vector3 point = axis.base.position_world(data);
  return {point, data.velocity_world[axis.base.link].point_velocity(point),
          data.X_world_link[axis.base.link].rotation() * axis.axis_base_link};
}

}  // namespace heavesim
