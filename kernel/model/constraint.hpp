#pragma once
// Constraints that close kinematic loops or tie coordinates together, as stored in
// the Model. Each is a set of scalar rows of Haug's basic kinds (E. J. Haug,
// Computer-Aided Kinematics and Dynamics of Mechanical Systems, 1989, ch. 3), written
// on frames A (on link_a) and B (on link_b):
//
//   along          d_A . (p_B - p_A) = 0        blocks translation along d (an axis of A)
//   perpendicular  a_A . b_B = 0                keeps an axis of A perpendicular to one of B
//   distance       (|p_B - p_A|^2 - L^2) / 2 = 0
//   coupler        q_a - ratio q_b - offset = 0 (coordinates of two 1-DoF joints)
//   driver         q_a,k - f(t) = 0            (prescribed motion of one joint coordinate)
//
// For every spatial row d(phi)/dt = G_B . (v_B - v_A) exactly, with G_B a world spatial
// force direction on B (and -G_B on A): this gives J, -dJ/dt v and the constraint's
// reaction wrench without finite differences (constraint_equations.hpp).
#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "kernel/joints/joint.hpp"
#include "kernel/spatial/transform.hpp"

namespace heavesim {

enum class ConstraintRowKind { along, perpendicular, distance, coupler, driver };

struct ConstraintRow {
  ConstraintRowKind kind = ConstraintRowKind::along;
  int axis_a = 0;  // along: axis of frame A (0 x, 1 y, 2 z); perpendicular: axis of A
  int axis_b = 0;  // perpendicular: axis of frame B
  std::string description;  // e.g. "translation along x"
};

/// A prescribed motion f(t) and its first two time derivatives, in the joint
/// coordinate's units (m, m/s, m/s^2 or rad, rad/s, rad/s^2).
struct DriverMotion {
  double position = 0.0;
  double velocity = 0.0;
  double acceleration = 0.0;
};
using DriverFunction = std::function<DriverMotion(double t)>;

/// The kinds of constraint, like the joint types (joint.hpp): each holds what only it
/// needs. Loop joints and distances act between frames A and B (the frame fields of
/// Constraint); couplers and drivers act on joint coordinates.
struct LoopJointConstraint {
  JointKind joint_kind = JointKind::fixed;  // the joint it stands for
};
struct DistanceConstraint {
  double distance = 0.0;  // m, between the frame origins
};
struct CouplerConstraint {
  int joint_a = 0, joint_b = 0;      // the two 1-DoF joints (model joint indices)
  double ratio = 1.0, offset = 0.0;  // q_a = ratio q_b + offset
};
struct DriverConstraint {
  int joint = 0;          // model joint index
  int coordinate = 0;     // which coordinate of the joint it prescribes
  DriverFunction motion;  // q_joint,coordinate = motion(t).position
};
using ConstraintKind = std::variant<LoopJointConstraint, DistanceConstraint, CouplerConstraint, DriverConstraint>;

struct Constraint {
  std::string name;
  ConstraintKind kind;
  // Frame constraints (loop joints, distances): frame A on link_a (the joint's parent
  // side), B on link_b.
  int link_a = 0, link_b = 0;
  Transform X_linkA_frame, X_linkB_frame;       // canonical frames (axis on z) in their links
  Matrix3 R_joint_frame = Matrix3::Identity();  // frame B's axes in the user's joint frame
  int first_row = 0;
  std::vector<ConstraintRow> rows;

  /// Whether it acts between frames A and B (loop joint, distance) rather than on coordinates.
  bool acts_on_frames() const {
    return std::holds_alternative<LoopJointConstraint>(kind) || std::holds_alternative<DistanceConstraint>(kind);
  }
  /// "loop joint", "distance constraint", "coupler" or "driver".
  const char* kind_name() const {
    static constexpr const char* names[] = {"loop joint", "distance constraint", "coupler", "driver"};
    return names[kind.index()];
  }
};

/// The rows that stand for a loop joint of this kind on canonical frames (axis on z;
/// universal: x on A, y on B): the complement of the joint's free motions.
std::vector<ConstraintRow> loop_joint_rows(JointKind kind);

}  // namespace heavesim
