#include "kernel/model/constraint.hpp"

#include "kernel/parameter_error.hpp"

namespace heavesim {
namespace {

ConstraintRow along(int axis) {
  static const char* names[3] = {"translation along x", "translation along y", "translation along z"};
  return {ConstraintRowKind::along, axis, 0, names[axis]};
}
/// a_A . b_B = 0 blocks the rotation about the third axis of the pair.
ConstraintRow perpendicular(int axis_a, int axis_b) {
  static const char* names[3] = {"rotation about x", "rotation about y", "rotation about z"};
  return {ConstraintRowKind::perpendicular, axis_a, axis_b, names[3 - axis_a - axis_b]};
}

}  // namespace

std::vector<ConstraintRow> loop_joint_rows(JointKind kind) {
  const ConstraintRow x = along(0), y = along(1), z = along(2);
  // Rotations: (x_A . z_B, y_A . z_B) keep z_B along z_A; x_A . y_B then fixes the twist.
  const ConstraintRow tilt_y = perpendicular(0, 2), tilt_x = perpendicular(1, 2), twist = perpendicular(0, 1);
  switch (kind) {
    case JointKind::fixed: return {x, y, z, tilt_x, tilt_y, twist};
    case JointKind::revolute: return {x, y, z, tilt_x, tilt_y};
    case JointKind::prismatic: return {x, y, tilt_x, tilt_y, twist};
    case JointKind::cylindrical: return {x, y, tilt_x, tilt_y};
    case JointKind::universal: return {x, y, z, twist};
    case JointKind::spherical: return {x, y, z};
    case JointKind::free: break;
  }
  throw ParameterError("type", "a free joint, which constrains nothing", "a joint type that can close a loop");
}

}  // namespace heavesim
